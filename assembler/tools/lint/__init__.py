"""``assembler lint``'s checks: problems MuJoCo accepts silently, each a :class:`Finding` with a code.

=====  ========  ===================================================================
code   severity  finding
=====  ========  ===================================================================
RA002  warning   a spec's lint.acknowledge entry that matches no finding (delete it)
RA101  error     parts overlap at the home pose (e.g. a gripper inside its wrist)
RA102  warning   gripper root body far (> 0.2 m) from the hand it is mounted on
RA201  warning   mass implausible for the geoms' volume (density outside 100..20000)
RA202  error     zero principal inertia, or an authored inertia that violates A+B>=C
RA203  warning   inertia larger than any mass inside the body's geoms could give
RA301  warning   position servo whose ctrlrange reaches outside its joint's range
RA302  warning   position-driven joint without a range
RA401  warning   armature from the inverse-index rule shrunk below 0.2
RA501  error     end-effector body or gripper site/geom/sensor missing from the model
RA502  warning   gripper with fingers but no left/right_fingerpad geoms declared
RA503  warning   important geom that cannot collide
RA504  warning   part with no visual geoms (invisible to robosuite's cameras)
RA601  error     home keyframe outside a joint's range
RA701  error     position servos robosuite's controllers would drive, robosuite.actuation unset
                 (warning with robosuite.enabled false), or actuation torque and a servo without forcerange
RA702  info      gripper without robosuite's eef body / grip sites (robosuite gets them at eef_body)
RA703  error     gripper with actuators but no actions: (robosuite refuses it)
RA704  info      arm without the {arm}_center site robosuite's composite controller reads
RA705  error     joint of a group robosuite's controllers drive without an actuator
RA706  error     base_xpos_offset of an arena other than table with variables
RA707  error     a part's file reads euler angles in another sequence than xyz
RA708  error     robosuite.controller that the bridge cannot build (info: robosuite absent)
RA801  error     MuJoCo Warp refuses an option: PGS solver, some flags, dense Jacobian past 60 dofs
RA802  error     MuJoCo Warp refuses an element: plugins, PID/SO3 actuators, flexvert equality
RA803  warning   constraint rows without contact exceed MuJoCo Warp's default njmax
       info      (or: how many contacts per world the default njmax leaves room for)
RA811  error     MJX has no collision function for two geoms that can collide (e.g. box-cylinder)
RA812  error     MJX refuses an option: IMPLICIT integrator, PGS solver, some enable flags
RA813  error     MJX refuses an element: flex, adhesion and other actuators, some sensors
RA814  error     MJX refuses margin/gap on a mesh or heightfield pair
RA815  warning   mesh hull too large for MJX (>200 vertices against primitives, >=32 mesh-mesh)
=====  ========  ===================================================================

Each check is a function ``(LintTarget) -> Iterator[Finding]``; :data:`CHECKS` runs them in order,
and ``lint(target, engine)`` adds :data:`ENGINE_CHECKS` for ``--target mjwarp`` (RA801-RA803) or
``--target mjx`` (RA811-RA815). A finding a part's spec acknowledges (``lint.acknowledge``, with a
reason) is reported as acknowledged and fails nothing (:mod:`assembler.tools.lint.acknowledgements`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from assembler.checks.finding import SEVERITIES, Finding, Severity
from assembler.checks.target import LintTarget, part_target, robot_target
from assembler.gpu.engines import ENGINES, Engine
from assembler.gpu.mjx_checks import (
    mjx_mesh_margins_and_sizes,
    mjx_missing_collisions,
    mjx_refused_elements,
    mjx_refused_options,
)
from assembler.gpu.warp_checks import warp_constraint_budget, warp_refused_elements, warp_refused_options
from assembler.robosuite.checks import (
    foreign_euler_sequences,
    grip_frames_added_for_robosuite,
    gripper_without_actions,
    missing_arm_centers,
    servos_robosuite_cannot_drive,
    undriven_controlled_joints,
    unreadable_base_offsets,
    unusable_controllers,
)
from assembler.tools.lint.acknowledgements import acknowledge
from assembler.tools.lint.actuators import ctrlrange_beyond_joint_range, unlimited_driven_joints
from assembler.tools.lint.armature import tiny_index_armature
from assembler.tools.lint.gripper_pose import gripper_root_far_from_hand
from assembler.tools.lint.important_names import (
    important_geoms_without_contact,
    missing_fingerpads,
    missing_important_names,
)
from assembler.tools.lint.keyframe import keyframe_outside_limits
from assembler.tools.lint.mass import degenerate_inertia, implausible_density, oversized_inertia
from assembler.tools.lint.penetration import self_penetration
from assembler.tools.lint.visibility import invisible_parts

Check = Callable[[LintTarget], Iterator[Finding]]

CHECKS: tuple[Check, ...] = (
    self_penetration,
    gripper_root_far_from_hand,
    implausible_density,
    degenerate_inertia,
    oversized_inertia,
    ctrlrange_beyond_joint_range,
    unlimited_driven_joints,
    tiny_index_armature,
    missing_important_names,
    missing_fingerpads,
    important_geoms_without_contact,
    invisible_parts,
    keyframe_outside_limits,
    servos_robosuite_cannot_drive,
    grip_frames_added_for_robosuite,
    gripper_without_actions,
    missing_arm_centers,
    undriven_controlled_joints,
    unreadable_base_offsets,
    foreign_euler_sequences,
    unusable_controllers,
)
"""Every check, in the order of their codes."""

ENGINE_CHECKS: dict[Engine, tuple[Check, ...]] = {
    "mujoco": (),
    "mjwarp": (warp_refused_options, warp_refused_elements, warp_constraint_budget),
    "mjx": (mjx_missing_collisions, mjx_refused_options, mjx_refused_elements, mjx_mesh_margins_and_sizes),
}
"""What ``--target`` adds to :data:`CHECKS`: what that engine refuses or runs badly."""


def lint(target: LintTarget, engine: Engine = "mujoco") -> list[Finding]:
    """Every finding of every check on ``target`` (and ``engine``'s), acknowledged ones marked: those
    that fail first (errors), then by severity and code."""
    checks = (*CHECKS, *ENGINE_CHECKS[engine])
    findings = acknowledge(target, [finding for check in checks for finding in check(target)])
    return sorted(findings, key=lambda f: (not f.fails, SEVERITIES.index(f.severity), f.code))


__all__ = [
    "CHECKS",
    "ENGINES",
    "ENGINE_CHECKS",
    "SEVERITIES",
    "Check",
    "Engine",
    "Finding",
    "LintTarget",
    "Severity",
    "lint",
    "part_target",
    "robot_target",
]
