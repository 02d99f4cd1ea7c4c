"""The gripper spec: a hand attached at an arm's end-effector body."""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from assembler.spec.schema.common import NOT_BOOL, NonNegativeFloat
from assembler.spec.schema.gripper_actions import GripperActions
from assembler.spec.schema.parts import PartSpec

ROBOSUITE_SITES: dict[str, str] = {"grip_site": "grip_site", "grip_cylinder": "grip_site_cylinder"}
"""robosuite's gripper site roles and the names its own grippers give them."""

ROBOSUITE_SENSORS: dict[str, str] = {"force_ee": "force_ee", "torque_ee": "torque_ee"}
"""robosuite's gripper sensor roles and the names its own grippers give them."""


class GripperSpec(PartSpec):
    """A gripper or hand: its MJCF (one root body, an `eef` body at the grip point) and its semantics."""

    kind: Literal["gripper"]
    """Marks a gripper spec."""

    eef_body: str = "eef"
    """The body at the grip point, whose frame defines the gripper's rotation offset."""

    dof: Annotated[int | None, Field(ge=0), NOT_BOOL] = None
    """Number of actions the gripper takes; null: the number of ``actions`` (or of actuators without them)."""

    actions: GripperActions | None = None
    """How a policy's actions drive the actuators (robosuite's format_action); null: none declared, which
    robosuite refuses for a gripper with actuators (lint RA703)."""

    speed: NonNegativeFloat = 0.0
    """How far one step of an incremental action moves each output, out of its range -1..1 (robosuite's
    speed)."""

    root_body: str | None = None
    """The body of the MJCF the gripper is made of, with everything below it and the actuators and
    sensors of its joints: a jaw inside an arm's own file (SO-101, Fetch), which the robot's spec
    cuts from the arm with remove_bodies; null: the file's one root body."""

    root_pose: Literal["file", "reset"] = "file"
    """file: the root body keeps the pose its file gives it, relative to the hand it is mounted on (as
    robosuite's grippers do); reset: the root sits at the hand's origin, unrotated, for a hand whose
    file places it somewhere in a scene (lint RA102). A robot's gripper_mount overrides either."""

    important_sites: dict[str, str] = Field(default_factory=dict)
    """Role -> site name; every site named must exist in the MJCF. robosuite's roles grip_site and
    grip_cylinder need no entry: they are the sites grip_site and grip_site_cylinder where the MJCF
    has them, and robosuite's bridge adds them where it has not (lint RA702)."""

    important_geoms: dict[str, list[str]] = Field(default_factory=dict)
    """Role (e.g. left_fingerpad) -> geom names; every geom must exist in the MJCF."""

    important_sensors: dict[str, str] = Field(default_factory=dict)
    """Role -> sensor name; every sensor named must exist in the MJCF. robosuite's roles force_ee and
    torque_ee need no entry: they are the sensors of those names where the MJCF has them, and
    robosuite's bridge adds them where it has not (lint RA702)."""

    @model_validator(mode="after")
    def _dof_matches_actions(self) -> GripperSpec:
        if self.actions is not None and self.dof is not None and self.dof != len(self.actions.dimensions):
            raise ValueError(
                f"dof is {self.dof} but actions declares {len(self.actions.dimensions)}; drop dof"
            )
        return self
