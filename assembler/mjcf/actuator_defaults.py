"""Actuator shortcuts get their gains from defaults as MuJoCo 3.16 and later define it, on every MuJoCo.

Before 3.16 a default class held one actuator default that every shortcut element (``<position>``,
``<motor>``, ``<muscle>``...) in the class wrote into without clearing it, and every actuator of
the class started from all of it. robosuite's Inspire hands declare, in their main default,
``<muscle ctrlrange=.../>``, ``<motor .../>`` and ``<position kp="10"/>``; on MuJoCo 3.9-3.15 their
position actuators keep the muscle's numbers where a position servo has none (``index_distal_drive``
gets biasprm ``[0.75, -2, -1]``: a constant force and a damping term), and Spot's motors carry the
position default's bias. MuJoCo 3.16 (changelog, Actuation 29, commit ab7f005c9) made a shortcut
inherit its parameters only from a default written with the same shortcut, or with ``general``
of the shortcut's gain type, looking up the class hierarchy for one, else its documented values;
each shortcut in a default resets the gains and dynamics of the ones before it; ``ctrlrange``,
``gear`` and the other mechanical attributes are inherited from any default, as before.

On older MuJoCo we apply that rule after parsing. For each actuator we work out, from the file's
``<default>`` tree, which default elements it inherits its parameters from under the new rule
(its *recipe*), let the installed MuJoCo parse a small file holding only those defaults and the
actuator itself, and copy the gain, bias, dynamics and activation fields to the real actuator.
MuJoCo's own parser computes every number; we only choose what it reads. Mechanical attributes
are left as the real parse set them, since both rules agree on them.

Compared with MuJoCo 4.0 on a table of class layouts (shortcut defaults in any order, nesting and
mix; ``general`` actuators; includes), the result is the same field for field, except where old
MuJoCo itself reads differently: a shortcut whose nearest usable default is a ``<general>`` that
sets raw gains keeps the raw values it does not overwrite (3.16 clears them; such a position
servo or motor is rare), a ``<cylinder bias>`` keeps only its first value, a ``<damper>`` loses
the ``kv`` of its class, and a file old MuJoCo refuses to parse stays refused.
"""

from __future__ import annotations

import functools
import xml.etree.ElementTree as ET
from collections.abc import Iterator, Mapping
from dataclasses import dataclass

import mujoco

from assembler.mjcf.installed_mujoco import mujoco_at_least

FIXED_IN: tuple[int, int] = (3, 16)
"""The first MuJoCo whose parser applies the rule itself; from it on this module does nothing."""

SHORTCUTS: frozenset[str] = frozenset(
    {"motor", "position", "velocity", "intvelocity", "damper", "cylinder", "muscle", "adhesion", "dcmotor"}
)
ACTUATOR_TAGS: frozenset[str] = SHORTCUTS | {"general", "plugin"}

MECHANICAL: frozenset[str] = frozenset(
    {
        "name", "class", "group", "ctrllimited", "ctrlrange", "forcelimited", "forcerange", "lengthrange",
        "gear", "cranklength", "inheritrange", "user", "nsample", "interp", "delay",
        "joint", "jointinparent", "tendon", "site", "refsite", "body", "cranksite", "slidersite",
    }
)  # fmt: skip
"""Attributes every default passes on, under both rules; the recipe leaves them out."""

PARAMETER_FIELDS: tuple[str, ...] = (
    "gaintype", "biastype", "dyntype", "gainprm", "biasprm", "dynprm",
    "actdim", "actearly", "actlimited", "actrange",
)  # fmt: skip
"""The ``MjsActuator`` fields a shortcut sets as a whole table under the new rule."""

Element = tuple[str, tuple[tuple[str, str], ...]]
"""A default or actuator element reduced to its tag and its non-mechanical attributes."""


def rule_is_native(version: str = mujoco.__version__) -> bool:
    """True when the installed MuJoCo already resolves actuator defaults by the 3.16 rule."""
    return mujoco_at_least(*FIXED_IN, version=version)


def _reduced(element: ET.Element) -> Element:
    kept = tuple((key, value) for key, value in element.attrib.items() if key not in MECHANICAL)
    return element.tag, kept


@dataclass(frozen=True)
class _Recipe:
    """The default elements, in order, from which an actuator inherits its parameters."""

    elements: tuple[Element, ...] = ()

    @property
    def kind(self) -> str:
        """The shortcut the default was last written with, or ``general``."""
        shortcuts = [tag for tag, _ in self.elements if tag in SHORTCUTS]
        return shortcuts[-1] if shortcuts else "general"

    def then(self, element: Element) -> _Recipe:
        return _Recipe((*self.elements, element))


def _xml(element: Element, extra: str = "") -> str:
    tag, attributes = element
    text = " ".join(f'{key}="{_escape(value)}"' for key, value in attributes)
    return f"<{tag} {text} {extra}/>"


def _escape(value: str) -> str:
    return value.replace("&", "&amp;").replace('"', "&quot;").replace("<", "&lt;")


def _nested(name: str, recipe: tuple[Element, ...]) -> str:
    """Default classes ``name``, ``name_1``... nested one per element (a class may hold each tag once);
    the innermost, which the actuator uses, is named ``name``."""
    if not recipe:
        return f'<default class="{name}"/>'
    inner = _nested(name, recipe[1:]) if len(recipe) > 1 else ""
    level = name if len(recipe) == 1 else f"{name}_{len(recipe)}"
    return f'<default class="{level}">{_xml(recipe[0])}{inner}</default>'


def _document(defaults: str, actuators: str) -> str:
    return f"<mujoco><default>{defaults}</default><actuator>{actuators}</actuator></mujoco>"


@functools.lru_cache(maxsize=256)
def _parsed_gaintype(text: str) -> int | None:
    try:
        return int(mujoco.MjSpec.from_string(text).actuators[0].gaintype)
    except ValueError:  # e.g. a bare <dcmotor/>: MuJoCo needs its motor constant
        return None


def _gaintype(recipe: _Recipe, shortcut: str = "general") -> int | None:
    """The gain type MuJoCo gives an actuator written with ``shortcut`` in a class built by
    ``recipe``; None where MuJoCo cannot read the shortcut without more attributes."""
    return _parsed_gaintype(_document(_nested("r", recipe.elements), f'<{shortcut} class="r"/>'))


def _compatible(recipe: _Recipe, shortcut: str) -> bool:
    """Whether ``shortcut`` may inherit the parameters of a default built by ``recipe``."""
    if recipe.kind == shortcut:
        return True
    gaintype = _gaintype(recipe)
    return recipe.kind == "general" and gaintype is not None and gaintype == _gaintype(_Recipe(), shortcut)


class _Classes:
    """Each default class's parent and final recipe, read from the file's ``<default>`` tree."""

    def __init__(self, root: ET.Element) -> None:
        self.parent: dict[str, str | None] = {}
        self.recipe: dict[str, _Recipe] = {}
        for top in root.findall("default"):
            self._walk(top, None, self.recipe.get("main", _Recipe()))

    def _walk(self, default: ET.Element, parent: str | None, inherited: _Recipe) -> None:
        name = default.get("class") or ("main" if parent is None else "")
        self.parent.setdefault(name, parent)
        recipe = inherited
        for child in default:
            if child.tag in ACTUATOR_TAGS - {"plugin"}:
                recipe = self.base(recipe, child.tag, parent).then(_reduced(child))
        self.recipe[name] = recipe
        for child in default.findall("default"):
            self._walk(child, name, recipe)

    def ancestors(self, name: str | None) -> Iterator[_Recipe]:
        while name is not None:
            yield self.recipe.get(name, _Recipe())
            name = self.parent.get(name)

    def base(self, current: _Recipe, tag: str, parent: str | None) -> _Recipe:
        """What an element ``tag`` starts from: ``current`` if it may inherit from it, else the
        nearest ancestor class's default it may inherit from, else nothing (its documented values)."""
        if tag == "general" or _compatible(current, tag):
            return current
        return next((r for r in self.ancestors(parent) if _compatible(r, tag)), _Recipe())


def _expanded(root: ET.Element, included: Mapping[str, bytes]) -> ET.Element:
    """A copy of ``root`` with each ``<include>`` replaced by the included file's elements."""
    copy = ET.fromstring(ET.tostring(root))

    def expand(parent: ET.Element) -> None:
        for index, child in reversed(list(enumerate(parent))):
            if child.tag == "include" and child.get("file") in included:
                parent.remove(child)
                inner = ET.fromstring(included[child.get("file") or ""])
                expand(inner)
                for offset, element in enumerate(inner):
                    parent.insert(index + offset, element)
            else:
                expand(child)

    expand(copy)
    return copy


def normalize_actuator_defaults(
    root: ET.Element, spec: mujoco.MjSpec, included: Mapping[str, bytes] | None = None
) -> None:
    """Give ``spec``'s actuators the parameters MuJoCo 3.16+ gives them (see the module docstring).

    ``root`` is the file's XML that ``spec`` was parsed from; ``included`` maps each ``<include
    file>`` value to that file's bytes. Does nothing on MuJoCo 3.16 and later, or when no default
    class holds an actuator default (where both rules agree).
    """
    if rule_is_native():
        return
    root = _expanded(root, included or {})
    if not any(e.tag in ACTUATOR_TAGS for d in root.iter("default") for e in d):
        return
    classes = _Classes(root)
    elements = [e for section in root.findall("actuator") for e in section]
    if len(elements) != len(spec.actuators):
        raise RuntimeError(f"{len(elements)} actuator elements in the XML, {len(spec.actuators)} in the spec")
    defaults, actuators = [], []
    for index, element in enumerate(elements):
        if element.tag == "plugin":
            actuators.append("<general/>")  # keeps the indices aligned; not copied back
            continue
        name = element.get("class") or "main"
        recipe = classes.base(classes.recipe.get(name, _Recipe()), element.tag, classes.parent.get(name))
        defaults.append(_nested(f"r{index}", recipe.elements))
        actuators.append(_xml(_reduced(element), f'class="r{index}"'))
    resolved = mujoco.MjSpec.from_string(_document("".join(defaults), "".join(actuators)))
    for element, ours, theirs in zip(elements, spec.actuators, resolved.actuators, strict=True):
        if element.tag != "plugin":
            for field in PARAMETER_FIELDS:
                setattr(ours, field, getattr(theirs, field))
