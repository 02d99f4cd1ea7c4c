"""``assembler build``: write a robot's standalone MJCF (to a file, a bundle folder or stdout), and
record the request so the same build next time is answered before any spec is read
(:mod:`assembler.cli.cached_build`)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.answers.request import record_answer
from assembler.cli.cached_build import build_flags, request_of, write_xml
from assembler.cli.common import assembled, idle_override_warnings, robot_name, use_cache
from assembler.gpu.put_model_check import check_with_mujoco_warp
from assembler.registry.instances import create_gripper
from assembler.registry.lookup import REGISTERED_GRIPPERS, REGISTERED_ROBOTS


def _gripper_alone(args: argparse.Namespace) -> bool:
    """Write the MJCF of a gripper spec built alone (``assembler build hand.yaml``), if ``args.robot``
    names one and no robot; return whether it did."""
    name = robot_name(args.robot)
    if name in REGISTERED_ROBOTS or name not in REGISTERED_GRIPPERS:
        return False
    _, spec = create_gripper(name, idn=args.idn).compile_alone_spec()
    write_xml(args, spec.to_xml(), name)
    return True


def run(args: argparse.Namespace) -> int:
    if _gripper_alone(args):
        return 0
    robot = assembled(args)
    xml = robot.get_xml(cache=use_cache(args))  # compiled first: a robot that does not compile writes nothing
    notes = idle_override_warnings(args)  # every --set checked before anything is written
    if args.target == "mjwarp":  # before writing: a model MuJoCo Warp refuses writes nothing either
        print(
            check_with_mujoco_warp(robot.get_model(cache=use_cache(args)), type(robot).__name__),
            file=sys.stderr,
        )
    write_xml(args, xml, type(robot).__name__)
    for note in notes:
        print(note, file=sys.stderr)
    request = request_of(args)
    if request is not None:
        record_answer(
            request, robot, [Path(folder) for folder in args.specs], build_flags(args).robot_file, notes
        )
    return 0
