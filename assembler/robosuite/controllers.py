"""Controller configurations for spec robots, where robosuite looks for them.

robosuite gives a robot its composite controller configuration in ``Robot.__init__``: the one passed
to ``robosuite.make``, else ``load_composite_controller_config(robot=<name>)``, which reads
``default_<name>.json`` by substring rules on the name (a robot named ``SparrowGR1`` gets GR1's
whole-body IK) and falls back to ``basic.json`` (every body part, one warning per part the robot
lacks). robosuite offers no other hook, and its tests forbid Robot subclasses, so this module wraps
that one function where robosuite binds it: a spec robot gets its spec's ``robosuite.controller``;
a robot of our own without one gets robosuite's default for its arms, plus the base, torso, head
and legs parts it has actuators for; everything else is robosuite's.
"""

from __future__ import annotations

import copy
import functools
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import robosuite
from robosuite.controllers.composite import composite_controller_factory as factory

from assembler import models
from assembler.errors import SpecError
from assembler.files.paths import confine, spec_homes
from assembler.models.registering import REGISTRIES
from assembler.robosuite.conventions import CONTROLLER, DRIVEN_GROUPS, base_in_robosuite, robot_type_name
from assembler.robosuite.make_records import (
    Facts,
    Origins,
    origins_of,
    recorded_facts,
    spec_class_of,
    spec_file,
)

ROBOSUITE_CONFIGS = Path(robosuite.__file__).parent / "controllers" / "config"
"""robosuite's configuration folder: ``robots/default_<robot>.json`` and ``default/composite/<type>.json``."""

DEFAULT_BY_ARMS: dict[str, str] = {"single": "default_panda", "bimanual": "default_baxter"}
"""robosuite's configuration for the arms of a robot that declares none."""

EXTRA_PARTS_FROM: dict[str, str] = {
    "base": "default_pandaomron",
    "torso": "default_pandaomron",
    "head": "basic",
    "legs": "basic",
}
"""Where a robot that declares no configuration gets one for each non-arm part it has actuators for."""

BINDINGS: tuple[str, ...] = (
    "robosuite.controllers.composite.composite_controller_factory",
    "robosuite.controllers",
    "robosuite.robots.robot",
    "robosuite",
)
"""The modules that hold ``load_composite_controller_config`` under that name."""

BASE_DRIVEN_BY: dict[str, set[str]] = {"WheeledRobot": {"base"}, "LeggedRobot": {"base"}}
"""The robot classes of robosuite that drive a base (with velocities, so not in ``DRIVEN_GROUPS``)."""

Loader = Callable[..., dict[str, Any]]
ROBOSUITES_LOADER: Loader = factory.load_composite_controller_config


def flattened(config: dict[str, Any]) -> dict[str, Any]:
    """robosuite's form of a configuration: ``body_parts.arms.{right,left}`` moved up into ``body_parts``."""
    config = copy.deepcopy(config)
    factory.validate_composite_controller_config(config)
    parts = config.pop("body_parts")
    arms = parts.pop("arms", {})
    config["body_parts"] = {**arms, **parts}
    return config


@functools.cache
def _robosuite_file(name: str) -> dict[str, Any]:
    """One of robosuite's configuration files by name: ``default_<robot>`` or a composite type."""
    for path in (
        ROBOSUITE_CONFIGS / "robots" / f"{name}.json",
        ROBOSUITE_CONFIGS / "default" / "composite" / f"{name.lower()}.json",
    ):
        if path.is_file():
            return json.loads(path.read_text())  # type: ignore[no-any-return]
    raise FileNotFoundError(name)


def robosuite_config_names() -> list[str]:
    """The names a spec may give as ``robosuite.controller``."""
    robots = sorted(path.stem for path in (ROBOSUITE_CONFIGS / "robots").glob("default_*.json"))
    composites = sorted(
        path.stem.upper() for path in (ROBOSUITE_CONFIGS / "default" / "composite").glob("*.json")
    )
    return composites + robots


def declared_config(
    robot_class: type[models.ManipulatorModel], read: Origins | None = None
) -> dict[str, Any] | None:
    """The configuration the spec's ``robosuite.controller`` gives, flattened; None when it gives none.
    A JSON file it names goes into ``read`` with its (size, mtime_ns) before it is read."""
    declared = robot_class.spec.robosuite.controller
    if declared is None:
        return None
    if isinstance(declared, dict):
        try:
            return flattened(declared)
        except (ValueError, KeyError, TypeError):
            raise SpecError(
                robot_class.spec_problem(
                    CONTROLLER, "a controller configuration needs 'type' and 'body_parts'"
                )
            ) from None
    if declared.endswith(".json"):
        document = robot_class.loaded.document if robot_class.loaded is not None else None
        folder = document.folder if document is not None and document.folder is not None else Path.cwd()
        try:  # the one door for what a spec reads: its folder, its repository's, the trusted ones
            path = confine(folder / declared, spec_homes(folder), "")
        except SpecError as error:
            raise SpecError(robot_class.spec_problem(CONTROLLER, str(error))) from None
        try:
            if read is not None:
                state = path.stat()
                read[str(path)] = (state.st_size, state.st_mtime_ns)
            return flattened(json.loads(path.read_text()))
        except OSError as error:
            raise SpecError(
                robot_class.spec_problem(CONTROLLER, f"cannot read {path}: {error.strerror}")
            ) from None
        except (ValueError, KeyError, TypeError):
            raise SpecError(
                robot_class.spec_problem(
                    CONTROLLER,
                    f"{path} is not a controller configuration (JSON with 'type' and 'body_parts')",
                )
            ) from None
    try:
        return flattened(_robosuite_file(declared))
    except FileNotFoundError:
        names = ", ".join(robosuite_config_names())
        raise SpecError(
            robot_class.spec_problem(
                CONTROLLER,
                f"robosuite has no controller configuration '{declared}'; it has {names}; "
                "or give a .json file or the configuration itself",
            )
        ) from None


def default_config(robot_class: type[models.ManipulatorModel]) -> dict[str, Any]:
    """robosuite's configuration for the robot's arms, plus the other parts it has actuators for on
    the base robosuite stands it on (its default base, or its stand-in base) that its robosuite Robot
    class drives: a FixedBaseRobot drives arms only, and a composite controller for parts nobody
    drives would add action dimensions that do nothing (HYBRID_MOBILE_BASE's base-mode flag)."""
    robot_type = robot_type_name(robot_class)
    driven = set(DRIVEN_GROUPS[robot_type]) | BASE_DRIVEN_BY.get(robot_type, set())
    robot = robot_class(idn=0)
    spec = robot_class.spec
    robot.add_base(REGISTRIES["base"].lookup(base_in_robosuite(spec))(idn=0))
    config = flattened(_robosuite_file(DEFAULT_BY_ARMS[robot.arm_type]))
    actuated = {
        "base": robot.base_actuators,
        "torso": robot.torso_actuators,
        "head": robot.head_actuators,
        "legs": robot.legs_actuators,
    }
    for part, actuators in actuated.items():
        actuated[part] = actuators if part in driven else []
        if actuated[part]:
            config["body_parts"][part] = copy.deepcopy(
                flattened(_robosuite_file(EXTRA_PARTS_FROM[part]))["body_parts"][part]
            )
    if actuated["base"] or actuated["torso"]:
        config["type"] = "HYBRID_MOBILE_BASE"
    return config


class ControllerConfigs:
    """The wrapper of robosuite's loader: which robots it answers for, and the answers."""

    def __init__(self) -> None:
        self.robots: dict[str, type] = {}
        """Robot name -> the robosuite class we registered for it (its ``assembler_class``, our class
        of that name, is read only when robosuite asks for its configuration)."""

        self.robosuites_own: set[str] = set()
        """Names of robosuite's own robots: without a declared configuration they keep robosuite's."""

    def load(self, controller: str | None = None, robot: str | None = None) -> dict[str, Any]:
        """robosuite's ``load_composite_controller_config``, answering for spec robots."""
        registered = self.robots.get(robot) if controller is None and robot is not None else None
        if registered is None or robot is None:
            return ROBOSUITES_LOADER(controller=controller, robot=robot)
        name = robot
        file = spec_file(registered)
        if file is not None:  # the configuration from its make record
            material: dict[str, Any] = {
                "family": "robot",
                "name": name,
                "file": file,
                "idn": "",
                "added": [],
                "controller": 1,
            }
            config = recorded_facts(material, lambda: self._recordable(registered, name))["config"]
            return copy.deepcopy(config) if config is not None else ROBOSUITES_LOADER(robot=name)
        config = self._config(registered.assembler_class, name)  # type: ignore[attr-defined]
        return config if config is not None else ROBOSUITES_LOADER(controller=None, robot=name)

    def _config(
        self, robot_class: type[models.ManipulatorModel], robot: str, read: Origins | None = None
    ) -> dict[str, Any] | None:
        """The configuration of a spec robot; None for robosuite's own (one of robosuite's names
        whose spec declares none). A JSON file it is read from goes into ``read``."""
        declared = declared_config(robot_class, read)
        if declared is not None:
            return declared
        if robot in self.robosuites_own:
            return None
        return default_config(robot_class)

    def _recordable(self, registered: type, robot: str) -> tuple[Facts, Origins]:
        """The configuration (:meth:`_config`) as a make record's values, with the files it depends on:
        the robot's and its base's specs and MJCF (a default configuration covers the base's
        actuators), and a JSON file it is read from."""
        robot_class: type[models.ManipulatorModel] = spec_class_of(registered)
        read: Origins = {}
        config = self._config(robot_class, robot, read)
        base = REGISTRIES["base"].lookup(base_in_robosuite(robot_class.spec))
        return {"config": config}, {**origins_of([robot_class(idn=0), base(idn=0)]), **read}

    def install(self) -> None:
        """Bind the wrapper where robosuite's modules hold the loader (code that imported it earlier keeps
        robosuite's)."""
        for module in BINDINGS:
            if module in sys.modules:
                # setattr: the loader is a module attribute robosuite's stubs do not declare
                setattr(sys.modules[module], "load_composite_controller_config", self.load)  # noqa: B010


CONFIGS = ControllerConfigs()
"""The one wrapper, installed by :mod:`assembler.robosuite`."""
