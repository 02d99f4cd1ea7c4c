"""The ``{arm}_center`` sites robosuite's composite controller needs, added where a robot has none.

robosuite's ``CompositeController.get_controller_base_pose`` reads the site ``{prefix}{arm}_center``
of every arm at each step: the frame the arm's controller takes as the robot's base. robosuite's own
robots carry one per arm at the origin of their root body; a robot from a URDF or a hand-written MJCF
often has none, and robosuite then fails at ``reset`` with "No site with name robot0_right_center".
For robosuite only, the robot's root body then gets the missing sites at its origin (where
robosuite's robots have theirs); our own builds are unchanged. Each addition is said once per build
inputs in a process (an :class:`~assembler.errors.AssemblerWarning`).
"""

from __future__ import annotations

import warnings

import mujoco

from assembler.errors import AssemblerWarning
from assembler.models import ManipulatorModel


def center_site(arm: str) -> str:
    """The unprefixed name robosuite looks the arm's base frame up by."""
    return f"{arm}_center"


def add_center_sites(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> None:
    """Give ``mjspec`` (the robot's part spec) a center site per arm where it has none (see the module)."""
    missing = [center_site(arm) for arm in robot.spec.arms if mjspec.site(center_site(arm)) is None]
    root = mjspec.worldbody.first_body()
    if not missing or root is None:
        return
    for name in missing:
        root.add_site(name=name, size=[0.01, 0.01, 0.01], rgba=[0, 0.8, 1, 0.3], group=2)
    root_name = root.name or "(unnamed)"
    warnings.warn(
        f"{robot.spec.name}: robosuite's controllers read the site{'s' if len(missing) > 1 else ''} "
        f"{', '.join(missing)}, which the model file lacks; added at the root body '{root_name}' for "
        "robosuite (add them to the model file to place them yourself)",
        AssemblerWarning,
        stacklevel=2,
    )
