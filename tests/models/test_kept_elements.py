"""A build never has fewer elements than its parts: a loss is a bug in the assembler and fails loudly."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest

import assembler
from assembler.mjcf.census import ElementsLost
from assembler.models import RobotModel
from assembler.models.preparation import PreparedPart
from assembler.spec.schema import SceneSpec
from assembler.worlds.scene import place_robots
from tests.conftest import TWO_LINK_MJCF, TWO_LINK_SPEC


def _leaky(cls: type[RobotModel]) -> type[RobotModel]:
    class Leaky(cls):  # type: ignore[misc, valid-type]
        """A hand-written part whose prepared spec holds a sensor of a joint that does not exist:
        copying the spec for the assembly drops it, in silence, as MjSpec.attach would."""

        def prepared(self) -> PreparedPart:
            prepared = super().prepared()
            if not any(sensor.name == "ghost" for sensor in prepared.mjspec.sensors):
                prepared.mjspec.add_sensor(
                    name="ghost", type=mujoco.mjtSensor.mjSENS_JOINTPOS, objtype=mujoco.mjtObj.mjOBJ_JOINT
                ).objname = "no_such_joint"
            return prepared

    return Leaky


def test_a_part_that_loses_an_element_on_the_way_into_the_assembly_fails_loudly(
    write: Callable[[str, str], Path],
) -> None:
    write("s/twolink.xml", TWO_LINK_MJCF)
    (cls,) = assembler.register_specs(write("s/robot.yaml", TWO_LINK_SPEC))
    with pytest.raises(ElementsLost) as error:
        _leaky(cls)(idn=0).get_model()
    assert str(error.value) == (
        "internal error, a bug in robot-assembler (please report it with the spec): building robot "
        "'Leaky' lost elements of its parts (sensors: 0 of 1)"
    )
    assert not isinstance(error.value, assembler.AssemblerError)  # not a user error: the CLI lets it crash


def test_a_robot_that_loses_an_element_in_a_scene_fails_the_scene_loudly(
    write: Callable[[str, str], Path],
) -> None:
    # a scene checks its robots' elements once, after the last robot (not once per robot)
    write("s/twolink.xml", TWO_LINK_MJCF)
    (cls,) = assembler.register_specs(write("s/robot.yaml", TWO_LINK_SPEC))
    entries = [{"robot": "TwoLink", "pos": [float(i), 0.0, 0.0]} for i in range(3)]
    scene = SceneSpec.model_validate({"kind": "scene", "name": "row", "robots": entries})
    whole = place_robots(scene, [cls(idn=i) for i in range(3)]).get_model()
    assert (whole.njnt, whole.nsensor) == (6, 0)
    with pytest.raises(ElementsLost) as error:
        place_robots(scene, [cls(idn=0), _leaky(cls)(idn=1), cls(idn=2)])
    assert str(error.value) == (
        "internal error, a bug in robot-assembler (please report it with the spec): building scene "
        "'row' lost elements of its parts (sensors: 0 of 1)"
    )


def test_what_the_spec_removes_is_not_counted_as_lost(write: Callable[[str, str], Path]) -> None:
    write("s/twolink.xml", TWO_LINK_MJCF)
    spec = write("s/robot.yaml", "name: TwoLink\nmjcf: twolink.xml\nremove_actuation: [elbow]\n")
    (cls,) = assembler.register_specs(spec)
    model = cls(idn=0).get_model()
    assert (model.njnt, model.nu) == (1, 1)


def test_geoms_mujoco_discards_on_the_files_request_are_not_counted_as_lost(
    write: Callable[[str, str], Path],
) -> None:
    discarding = TWO_LINK_MJCF.replace('autolimits="true"', 'autolimits="true" discardvisual="true"')
    mjcf = write("s/twolink.xml", discarding)
    (cls,) = assembler.register_specs(write("s/robot.yaml", TWO_LINK_SPEC))
    model = cls(idn=0).get_model()
    assert (model.ngeom, mujoco.MjModel.from_xml_path(str(mjcf)).ngeom, discarding.count("<geom")) == (
        3,
        3,
        4,
    )
