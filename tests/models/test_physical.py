"""``bodies:`` and ``geoms:`` entries: scaled links and set frictions in the compiled model, errors and provenance."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.cli import main
from assembler.errors import SpecError
from tests.conftest import TWO_LINK_MJCF

Write = Callable[[str, str], Path]


def _robot(write: Write, spec_body: str) -> assembler.RobotModel:
    write("r/twolink.xml", TWO_LINK_MJCF)
    spec = write("r/robot.yaml", "name: Scaled\nmjcf: twolink.xml\n" + spec_body)
    (cls,) = assembler.register_specs(spec)
    return cls(idn=0)


def _model(overrides: dict[str, object] | None = None) -> mujoco.MjModel:
    return assembler.assemble("Sparrow7", overrides=overrides).get_model(cache=False, store=False)


def test_size_scale_grows_a_link_with_mass_cubed_and_inertia_to_the_fifth() -> None:
    plain = _model()
    scaled = _model({"bodies": [{"match": "link4", "size_scale": 1.25}]})
    link, child = plain.body("robot0_link4").id, plain.body("robot0_link5").id
    assert scaled.body_mass[link] == pytest.approx(plain.body_mass[link] * 1.25**3, rel=1e-12)
    np.testing.assert_allclose(scaled.body_inertia[link], plain.body_inertia[link] * 1.25**5, rtol=1e-9)
    np.testing.assert_allclose(scaled.body_ipos[link], plain.body_ipos[link] * 1.25, rtol=1e-12)
    np.testing.assert_allclose(scaled.body_pos[child], plain.body_pos[child] * 1.25, rtol=1e-12)
    for geom in np.flatnonzero(plain.geom_bodyid == link):
        np.testing.assert_allclose(scaled.geom_size[geom], plain.geom_size[geom] * 1.25, rtol=1e-12)
        np.testing.assert_allclose(scaled.geom_pos[geom], plain.geom_pos[geom] * 1.25, atol=1e-12)
    # the link's own offset from its parent is the parent's length: unchanged
    np.testing.assert_array_equal(scaled.body_pos[link], plain.body_pos[link])
    others = np.arange(plain.nbody) != link
    np.testing.assert_array_equal(scaled.body_mass[others], plain.body_mass[others])


def test_mass_scale_with_size_scale_replaces_the_cube_and_inertia_follows_the_mass() -> None:
    plain = _model()
    scaled = _model({"bodies": [{"match": "link[23]", "mass_scale": 0.5, "size_scale": 2.0}]})
    for name in ("robot0_link2", "robot0_link3"):
        body = plain.body(name).id
        assert scaled.body_mass[body] == pytest.approx(plain.body_mass[body] * 0.5, rel=1e-12)
        np.testing.assert_allclose(scaled.body_inertia[body], plain.body_inertia[body] * 0.5 * 4, rtol=1e-9)


def test_a_body_without_inertial_is_scaled_through_its_geoms(write: Write) -> None:
    robot = _robot(write, "bodies:\n  - {match: link1, size_scale: 2.0}\n  - {match: link2, mass_scale: 3}\n")
    plain = _robot_model(write)
    model = robot.get_model(cache=False, store=False)
    link1, link2 = plain.body("robot0_link1").id, plain.body("robot0_link2").id
    assert model.body_mass[link1] == pytest.approx(plain.body_mass[link1] * 8, rel=1e-9)
    np.testing.assert_allclose(model.body_inertia[link1], plain.body_inertia[link1] * 32, rtol=1e-9)
    np.testing.assert_allclose(model.body_pos[link2], plain.body_pos[link2] * 2, rtol=1e-12)
    assert model.body_mass[link2] == pytest.approx(plain.body_mass[link2] * 3, rel=1e-9)


def _robot_model(write: Write) -> mujoco.MjModel:
    write("p/twolink.xml", TWO_LINK_MJCF)
    (cls,) = assembler.register_specs(write("p/plain.yaml", "name: Plain\nmjcf: twolink.xml\n"))
    return cls(idn=0).get_model(cache=False, store=False)


CUBE_OBJ = "".join(f"v {x} {y} {z}\n" for x in (0, 1) for y in (0, 1) for z in (0, 1)) + (
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
)

MESH_MJCF = """\
<mujoco model="meshy">
  <asset><mesh name="block" file="block.obj" scale="0.1 0.1 0.2"/></asset>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="mesh" mesh="block"/>
      <body name="link1" pos="0 0 0.2">
        <joint name="j1" axis="0 0 1"/>
        <geom name="link1_col" type="mesh" mesh="block"/>
        <body name="right_hand" pos="0 0 0.2"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def _mesh_robot(write: Write, spec_body: str) -> assembler.RobotModel:
    write("m/block.obj", CUBE_OBJ)
    write("m/meshy.xml", MESH_MJCF)
    (cls,) = assembler.register_specs(write("m/meshy.yaml", "name: Meshy\nmjcf: meshy.xml\n" + spec_body))
    return cls(idn=0)


def test_mesh_geoms_are_scaled_through_their_mesh(write: Write) -> None:
    model = _mesh_robot(write, "bodies:\n  - {match: '*', size_scale: 1.5}\n").get_model(
        cache=False, store=False
    )
    np.testing.assert_allclose(model.mesh_scale[0], [0.15, 0.15, 0.3], rtol=1e-12)
    np.testing.assert_allclose(np.ptp(model.mesh_vert, axis=0), [0.15, 0.15, 0.3], rtol=1e-6)


def test_a_mesh_shared_by_bodies_scaled_differently_is_refused(write: Write) -> None:
    robot = _mesh_robot(write, "bodies:\n  - {match: link1, size_scale: 1.5}\n")
    with pytest.raises(SpecError) as caught:
        robot.check()
    assert str(caught.value).endswith(
        "meshy.yaml:4:32: bodies[0].size_scale: mesh 'block' is used by bodies 'base' (size_scale 1) and "
        "'link1' (size_scale 1.5); a mesh is scaled as a whole: give these bodies the same size_scale"
    )


def test_geom_friction_is_set_on_the_matched_geoms_only() -> None:
    plain = _model()
    model = _model({"geoms": [{"match": "link7_*", "friction": [0.4, 0.01, 0.0002]}]})
    matched = [g for g in range(plain.ngeom) if plain.geom(g).name.startswith("robot0_link7_")]
    assert matched
    for geom in range(plain.ngeom):
        expected = [0.4, 0.01, 0.0002] if geom in matched else plain.geom_friction[geom]
        np.testing.assert_allclose(model.geom_friction[geom], expected)


def test_entries_matching_nothing_are_errors_at_their_lines_listing_what_exists(write: Write) -> None:
    robot = _robot(
        write,
        "bodies:\n  - {match: link9, mass_scale: 2}\ngeoms:\n  - {match: link3_col, friction: [1, 0, 0]}\n",
    )
    with pytest.raises(SpecError) as caught:
        robot.check()
    lines = str(caught.value).splitlines()
    assert len(lines) == 2
    assert lines[0].endswith(
        "r/robot.yaml:4:13: bodies[0].match: no body matches 'link9'. "
        "Did you mean 'link2'? Bodies: base, link1, link2, right_hand"
    )
    assert lines[1].endswith(
        "r/robot.yaml:6:13: geoms[0].match: no geom matches 'link3_col'. "
        "Did you mean 'link2_col'? Geoms: base_col, link1_col, link1_vis, link2_col"
    )


@pytest.mark.parametrize(
    ("entry", "message"),
    [
        ("{match: link1}", "bodies[0]: entry for 'link1' sets nothing; give mass_scale or size_scale"),
        ("{match: link1, size_scale: 0}", "bodies[0].size_scale: Input should be greater than 0"),
        ("{match: link1, mass_scale: .nan}", "bodies[0].mass_scale: Input should be a finite number"),
    ],
)
def test_invalid_body_entries_say_the_rule(write: Write, entry: str, message: str) -> None:
    with pytest.raises(SpecError, match=message.replace("[", r"\[").replace("]", r"\]")):
        _robot(write, f"bodies:\n  - {entry}\n")


def test_inspect_names_the_entry_behind_each_factor_and_friction(capsys: pytest.CaptureFixture[str]) -> None:
    flags = ["--set", "bodies=[{match: link4, size_scale: 1.5}, {match: link4, mass_scale: 2}]"]
    flags += ["--set", "geoms=[{match: link7_col, friction: [0.3, 0.01, 0.001]}]"]
    assert main(["inspect", "Sparrow7", *flags, "--format", "json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert report["bodies"] == {
        "robot0_link4": {
            "size_scale": {"value": 1.5, "source": "spec bodies[0]"},
            "mass_scale": {"value": 2.0, "source": "spec bodies[1]"},
        }
    }
    assert report["geoms"] == {
        "robot0_link7_col": {"friction": {"value": [0.3, 0.01, 0.001], "source": "spec geoms[0]"}}
    }
    assert main(["inspect", "Sparrow7", *flags]) == 0
    rows = [line.split() for line in capsys.readouterr().out.splitlines()]
    assert ["robot0_link4", "2", "1.5", "4.5", "-", "spec", "bodies[0],", "spec", "bodies[1]"] in rows
