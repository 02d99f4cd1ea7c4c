"""MuJoCo's own load of a vendor's file, the reference the corpus compares our build with: an MJCF
as ``MjModel.from_xml_path`` reads it; a URDF through MuJoCo's URDF import with bodies unfused (so
that they correspond one to one), visual geoms kept, mesh paths as written (``package://NAME/``
resolved through ROS_PACKAGE_PATH, as a user sets it) and MuJoCo's ``balanceinertia`` where the
spec balances inertias.

A task scene (gymnasium-robotics' Fetch and Shadow hand) is compared as the robot alone: MuJoCo's own
load of the vendor's file with the scene deleted through MuJoCo's model editing (``MjSpec.delete``),
by the rule the docs give, not by the spec's ``mjcf_fixes``: every child of ``<worldbody>`` but the
robot's root body, and every equality, contact pair or exclusion, actuator and sensor naming a body,
geom or site deleted. What ``assembler new`` cut is thus checked against an independent cut."""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any

import mujoco

from assembler.urdf.packages import package_folders


def _packages(text: str) -> str:
    for folder in filter(None, os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep)):
        for package in set(re.findall(r"package://([^/]+)/", text)):
            root = Path(folder) if Path(folder).name == package else Path(folder) / package
            if root.is_dir():  # an entry is the package itself or holds it (as ROS reads it)
                text = text.replace(f"package://{package}/", f"{root}/")
    for package in set(re.findall(r"package://([^/]+)/", text)):  # a share/ tree (example-robot-data)
        found = package_folders(package)
        if found:
            text = text.replace(f"package://{package}/", f"{found[0]}/")
    return text


def reads_collada(path: Path) -> bool:
    """Whether the URDF names COLLADA meshes, which MuJoCo alone cannot read (the assembler converts
    them to OBJ, docs/urdf.md): MuJoCo's own load has nothing to compare with."""
    return bool(re.search(r"\.dae[\"']", path.read_text(), re.IGNORECASE))


def _subtree_names(body: Any) -> set[str]:
    """The names of the body and of every body, geom and site below it."""
    elements = [body, *body.find_all("body"), *body.find_all("geom"), *body.find_all("site")]
    return {element.name for element in elements if element.name}


def robot_alone(spec: mujoco.MjSpec, root: str) -> mujoco.MjSpec:
    """``spec`` without anything of its world but the body ``root`` and what lies below it."""
    world = spec.worldbody
    gone: set[str] = set()
    beside = [body for body in world.bodies if body.name != root]
    for body in beside:
        gone |= _subtree_names(body)
    for element in [*beside, *world.geoms, *world.sites, *world.lights, *world.cameras]:
        gone.add(element.name)
        spec.delete(element)
    gone.discard("")
    naming = [
        *(item for item in spec.equalities if {item.name1, item.name2} & gone),
        *(item for item in spec.excludes if {item.bodyname1, item.bodyname2} & gone),
        *(item for item in spec.pairs if {item.geomname1, item.geomname2} & gone),
        *(item for item in spec.actuators if item.target in gone),
        *(item for item in spec.sensors if {item.objname, item.refname} & gone),
    ]
    for item in naming:
        spec.delete(item)
    return spec


def direct_load(path: Path, urdf: bool, spec: Any, root: str | None = None) -> mujoco.MjModel:
    """The vendor's file as MuJoCo alone loads it; with ``root``, the robot of that root body alone."""
    if not urdf:
        loaded = mujoco.MjSpec.from_file(str(path))
        return (robot_alone(loaded, root) if root else loaded).compile()
    balance = str(bool(spec.balance_inertia)).lower()
    compiler = (
        f'<mujoco><compiler fusestatic="false" discardvisual="false" strippath="false" '
        f'meshdir="{path.parent}" balanceinertia="{balance}"/></mujoco>'
    )
    text = re.sub(r"(<robot[^>]*>)", lambda match: match.group(1) + compiler, path.read_text(), count=1)
    loaded = mujoco.MjSpec.from_string(_packages(_sized_visuals(text)))
    if getattr(spec, "add_free_joint", False):  # a URDF declares no floating base; the spec adds one
        loaded.worldbody.bodies[0].add_freejoint()
    return loaded.compile()


def _sized_visuals(text: str) -> str:
    """The URDF without the visuals of a size MuJoCo cannot compile (which its import, discarding every
    visual by default, never compiles): the read leaves them out and says so."""
    return re.sub(
        r"<visual>(?:(?!</visual>).)*?<(?:sphere|cylinder|capsule) radius=\"0(?:\.0*)?\"(?:(?!</visual>).)*?</visual>",
        "",
        text,
        flags=re.S,
    )
