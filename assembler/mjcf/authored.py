"""Which joint attributes an MJCF file sets, by MuJoCo's own default resolution.

robosuite's rule "apply the default only where the model does not set it" needs to know whether
a joint's damping (say) comes from the file or from MuJoCo's built-in default. MjSpec reports
resolved values only, so we ask MuJoCo itself: parse the file a second time with an impossible
sentinel value in the main default class. A joint that still shows the sentinel inherits from
nothing the author wrote; any other value was set by the author, literally, through its class,
a nested class or an ancestor's ``childclass`` - exactly as MuJoCo will compile it.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Mapping

import mujoco

from assembler.mjcf import mujoco_warnings
from assembler.mjcf.joints import joint_attribute

SENTINEL = -7.251e33
"""A value no author writes; it marks attributes the file leaves to MuJoCo's built-in default."""

SENSED_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature", "stiffness")


def _main_joint_default(root: ET.Element) -> ET.Element:
    default = root.find("default")
    if default is None:
        default = ET.SubElement(root, "default")
    joint = default.find("joint")
    if joint is None:
        joint = ET.SubElement(default, "joint")
    return joint


Authored = dict[str, tuple[str, str]]
"""Attribute -> (how, class name): how is ``literal`` (on the joint element), ``main default``
(the file's class-less ``<default>``) or ``class`` (a default class, nested class or ``childclass``)."""


def authored_attributes(
    root: ET.Element, mjspec: mujoco.MjSpec, included: Mapping[str, bytes] | None = None
) -> list[Authored]:
    """For each joint of ``mjspec`` (in MjSpec order), the attributes the file sets and how.

    ``root`` is the file's parsed XML; it is not modified. ``included`` maps each ``<include file>``
    value to that file's bytes: the probe is parsed from memory, where MuJoCo cannot open files.
    """
    probe_root = ET.fromstring(ET.tostring(root))
    main_joint = _main_joint_default(probe_root)
    in_main = {a for a in SENSED_ATTRIBUTES if main_joint.get(a) is not None}
    for attribute in SENSED_ATTRIBUTES:
        if attribute not in in_main:
            main_joint.set(attribute, repr(SENTINEL))
    probe_xml = ET.tostring(probe_root, encoding="unicode")
    with mujoco_warnings.collected():  # the file's own parse has shown them
        probe = mujoco.MjSpec.from_string(probe_xml, include=dict(included or {}))

    literal = {
        element.get("name"): element.attrib
        for element in root.iter("joint")
        if element.get("name") and element.get("joint") is None and element.get("joint1") is None
    }
    result: list[Authored] = []
    for joint, probed in zip(mjspec.joints, probe.joints, strict=True):
        own = literal.get(joint.name, {})
        sets: Authored = {}
        for attribute in SENSED_ATTRIBUTES:
            if attribute in own:
                sets[attribute] = ("literal", "")
            elif attribute in in_main:
                sets[attribute] = ("main default", "")
            elif joint_attribute(probed, attribute) != SENTINEL:
                sets[attribute] = ("class", joint.classname.name)
        result.append(sets)
    return result
