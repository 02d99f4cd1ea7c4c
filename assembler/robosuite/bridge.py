"""The bridge itself: imports robosuite, then registers our specs with it (see :mod:`assembler.robosuite`).

Importing this module imports robosuite, patches the statements of robosuite this MuJoCo cannot run
(:mod:`.compat`), then registers each shipped spec whose name robosuite does
not use itself, then the spec folders and experiment file named by ``ASSEMBLER_ROBOSUITE_SPECS``
and ``ASSEMBLER_ROBOSUITE_EXPERIMENT``. Our specs of robosuite's own robots, grippers and bases
enter only when asked: ``replace_robosuite()`` (robosuite's test plugin does this). What reaches the
simulator is our assembly, emitted so that robosuite's XML layer reads it without loss
(``docs/robosuite.md``).
"""

from __future__ import annotations

import sys

try:
    import robosuite  # noqa: F401  (robosuite's registries must exist before we write to them)
except ImportError as error:  # pragma: no cover - depends on the installation
    raise ImportError(
        f"assembler.robosuite needs robosuite ({error}); install it with: pip install -e '.[robosuite]'"
    ) from None

from assembler import models
from assembler.errors import Problem, RegistryError, did_you_mean
from assembler.models.registering import REGISTRIES, Registry
from assembler.registry.shipped import hold_shipped_names
from assembler.robosuite import compat
from assembler.robosuite.autoload import register, register_experiment, register_from_environment
from assembler.robosuite.controllers import CONFIGS
from assembler.robosuite.conventions import offered
from assembler.robosuite.registrations import family_of as _family_of
from assembler.robosuite.registrations import recorded
from assembler.robosuite.registries import TABLES, Installable, install, installed, replaced, robosuite_has

__all__ = ["register", "register_experiment", "registered", "replace_robosuite", "replaced"]


def _shipped() -> list[Installable]:
    """What enters robosuite at import. A shipped spec of a name robosuite uses itself enters only
    through ``replace_robosuite``, so its file stays unread until something looks the name up (44
    of the 63 shipped specs); every other held name enters by its registration record, or is made
    here (and recorded) when it has none (:mod:`.registrations`); and every class already made
    (a user's folder registered before robosuite loaded) enters as it is."""
    found: dict[tuple[str, str], Installable] = {}
    for family, table in _bases_first():
        for name in table.held_names():
            if not robosuite_has(family, name):
                registration = recorded(family, name)  # None: the spec was read, its class made
                if registration is not None and registration.offered:
                    found[(registration.family, name)] = registration
    for table in REGISTRIES.values():
        for cls in table.made():
            if _enters_robosuite(cls):
                found.setdefault((_family_of(cls), cls.__name__), cls)
    return list(found.values())


def _bases_first() -> list[tuple[str, Registry[models.PartModel]]]:
    """The registries, bases first: a robot's base is read to record the robot (its type decides the
    robot's Robot type), so a base read before its own record is looked for is recorded too."""
    return sorted(REGISTRIES.items(), key=lambda item: item[0] != "base")


def _enters_robosuite(cls: type[models.PartModel]) -> bool:
    if not offered(cls):
        return False
    try:
        return not robosuite_has(_family_of(cls), cls.__name__)
    except RegistryError:  # robots without arms have no place in robosuite
        return False


def replace_robosuite(names: list[str] | None = None) -> list[str]:
    """Replace robosuite's own robots, grippers and bases by our specs of the same names (all of them
    when ``names`` is None); returns the names replaced. A shipped spec not read yet is installed
    from its registration record when it has one, and read when it is used."""
    found: dict[str, Installable] = {}
    for family, table in _bases_first():
        for name in table.held_names():
            if (names is None or name in names) and robosuite_has(family, name):
                registration = recorded(family, name)  # None: the spec was read, its class made
                if registration is not None:
                    found[name] = registration
        for cls in table.made():
            name = cls.__name__
            if (names is None or name in names) and robosuite_has(_family_of(cls), name):
                found.setdefault(name, cls)
    unknown = sorted(set(names or []) - set(found))
    if unknown:
        raise RegistryError([Problem(_why_not_replaced(name)) for name in unknown])
    return install(found.values(), replace=True)


def _why_not_replaced(name: str) -> str:
    """Why ``replace_robosuite`` cannot replace ``name``: not robosuite's, or no spec of that name."""
    specs = {spec_name for table in REGISTRIES.values() for spec_name in table}
    robosuites = {
        str(other) for family in TABLES for other in TABLES[family][0] if robosuite_has(family, str(other))
    }
    if name in specs:
        return (
            f"replace_robosuite: {name} is not robosuite's; robosuite finds our {name} by that name already"
        )
    if name in robosuites:
        return f"replace_robosuite: robosuite's {name} has no spec of that name to replace it"
    hint = did_you_mean(name, specs & robosuites)
    return f"replace_robosuite: neither robosuite nor the specs know {name}.{hint}"


def registered() -> dict[str, list[str]]:
    """Per family (robot, gripper, base), the names robosuite resolves to our specs."""
    return {family: installed(family) for family in ("robot", "gripper", "base")}


compat.apply_all()  # before anything of robosuite runs: robosuite's statements newer MuJoCo breaks
CONFIGS.install()
hold_shipped_names()  # by name: a spec is read (the schema imported) only when its name is made
install(_shipped())
ENVIRONMENT_PROBLEMS: list[str] = register_from_environment()
"""What ``ASSEMBLER_ROBOSUITE_SPECS``/``_EXPERIMENT`` named that could not be registered, one line each
(printed here; ``python -m assembler.robosuite`` stops on them)."""
for _line in ENVIRONMENT_PROBLEMS:
    print(_line, file=sys.stderr)
