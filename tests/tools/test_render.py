"""``assembler render``: a real offscreen render, written as a PNG this test decodes itself."""

from __future__ import annotations

import os
import struct
import subprocess
import sys
import zlib
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.cli import arguments, main
from assembler.models import PartModel, RobotModel
from assembler.models.geom_groups import geoms_by_part
from assembler.tools.render import LABELS, VIEWS, encode_png
from assembler.tools.render.picture import render_views
from assembler.tools.render.stage import FLOOR, HIDDEN_GROUP, Stage, build_stage

WIDTH, HEIGHT = 240, 180


def decode_png(data: bytes) -> np.ndarray:
    """An 8-bit RGB PNG as an (height, width, 3) array: chunks, CRCs, zlib and all five row filters."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    position, chunks = 8, {}
    while position < len(data):
        (length,) = struct.unpack(">I", data[position : position + 4])
        kind, payload = data[position + 4 : position + 8], data[position + 8 : position + 8 + length]
        (crc,) = struct.unpack(">I", data[position + 8 + length : position + 12 + length])
        assert crc == zlib.crc32(kind + payload), kind
        chunks[kind] = chunks.get(kind, b"") + payload
        position += 12 + length
    width, height, depth, color, _, _, interlace = struct.unpack(">IIBBBBB", chunks[b"IHDR"])
    assert (depth, color, interlace) == (8, 2, 0)
    raw = zlib.decompress(chunks[b"IDAT"])
    stride, previous = width * 3, [0] * width * 3
    rows = []
    for y in range(height):
        kind, line = raw[y * (stride + 1)], list(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - 3] if x >= 3 else 0
            b, c = previous[x], previous[x - 3] if x >= 3 else 0
            if kind == 1:
                line[x] = (line[x] + a) & 0xFF
            elif kind == 2:
                line[x] = (line[x] + b) & 0xFF
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 0xFF
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 0xFF
        rows.append(line)
        previous = line
    return np.array(rows, dtype=np.uint8).reshape(height, width, 3)


@pytest.fixture(scope="module")
def sparrow_stage() -> Stage:
    """Sparrow7 on its pedestal, staged once. No skip without OpenGL: these tests then fail with the
    same one-line RenderError (what to set) that users see."""
    return build_stage(assembler.assemble("Sparrow7"), WIDTH, HEIGHT)


def robot_mask(stage: Stage, image: np.ndarray, view: str) -> np.ndarray:
    """Pixels where the robot is: those that change when every geom but the floor is hidden."""
    groups = stage.model.geom_group.copy()
    stage.model.geom_group[:] = HIDDEN_GROUP
    stage.model.geom_group[stage.floor] = groups[stage.floor]
    try:
        (empty,) = render_views(stage, [view], image.shape[1], image.shape[0])
    finally:
        stage.model.geom_group[:] = groups
    return np.abs(image.astype(int) - empty.astype(int)).max(axis=2) > 24


def test_png_round_trips_through_an_independent_decoder() -> None:
    rng = np.random.default_rng(0)
    gradient = np.broadcast_to(np.arange(64, dtype=np.uint8)[None, :, None] * 4, (32, 64, 3))
    for image in (rng.integers(0, 256, (17, 23, 3), dtype=np.uint8), np.ascontiguousarray(gradient)):
        assert np.array_equal(decode_png(encode_png(image)), image)


def test_render_writes_a_png_with_the_robot_centred_and_filling_the_frame(
    sparrow_stage: Stage, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "sparrow.png"
    code = main(["render", "Sparrow7", "-o", str(target), "--views", "iso", "--size", f"{WIDTH}x{HEIGHT}"])
    assert code == 0
    assert capsys.readouterr().err == f"wrote {target} ({WIDTH}x{HEIGHT}, iso; geom groups 1, 2)\n"
    image = decode_png(target.read_bytes())
    assert image.shape == (HEIGHT, WIDTH, 3)
    assert image.std() > 20  # not blank
    mask = robot_mask(sparrow_stage, image, "iso")
    ys, xs = np.nonzero(mask)
    assert 0.05 < mask.mean() < 0.6
    assert abs(xs.mean() / WIDTH - 0.5) < 0.15 and abs(ys.mean() / HEIGHT - 0.5) < 0.15
    # auto-framing: the robot spans most of the frame's height (it is taller than wide)
    assert (ys.max() - ys.min()) / HEIGHT > 0.75
    assert ys.min() > 0 and ys.max() < HEIGHT - 1  # but is not cut off


def test_views_are_tiled_in_order(sparrow_stage: Stage) -> None:
    views = ["front", "side", "top", "iso"]
    tiles = render_views(sparrow_stage, views, WIDTH, HEIGHT)
    masks = [robot_mask(sparrow_stage, tile, view) for tile, view in zip(tiles, views, strict=True)]
    assert all(mask.mean() > 0.03 for mask in masks)
    # the arm reaches forward (+x): seen from the side it is wider than seen from the front
    spans = [np.ptp(np.nonzero(mask)[1]) for mask in masks]
    assert spans[1] > 1.5 * spans[0]


def test_cli_tiles_four_views_two_by_two(tmp_path: Path, sparrow_stage: Stage) -> None:
    target = tmp_path / "views.png"
    assert (
        main(["render", "Sparrow7", "-o", str(target), "--views", "front,side,top,iso", "--size", "120x90"])
        == 0
    )
    image = decode_png(target.read_bytes())
    assert image.shape == (180, 240, 3)
    tiles = [image[r : r + 90, c : c + 120] for r in (0, 90) for c in (0, 120)]
    assert all(tile.std() > 10 for tile in tiles)
    assert not np.array_equal(tiles[0], tiles[1])


def test_joint_labels_are_drawn(sparrow_stage: Stage) -> None:
    (plain,) = render_views(sparrow_stage, ["side"], WIDTH, HEIGHT)
    (labelled,) = render_views(sparrow_stage, ["side"], WIDTH, HEIGHT, labels="joints")
    changed = np.abs(plain.astype(int) - labelled.astype(int)).max(axis=2) > 60
    assert changed.mean() > 0.01


def test_unknown_view_is_one_line(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code = main(["render", "Sparrow7", "-o", str(tmp_path / "x.png"), "--views", "front,fron"])
    assert code == 1
    assert capsys.readouterr().err == "unknown view(s): fron; choose from front, side, top, iso\n"
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(
    not sys.platform.startswith("linux") or bool(os.environ.get("DISPLAY")), reason="needs a headless Linux"
)
def test_without_a_display_glfw_fails_with_what_to_set(tmp_path: Path) -> None:
    env = {k: v for k, v in os.environ.items() if k not in ("DISPLAY", "WAYLAND_DISPLAY")}
    env["MUJOCO_GL"] = "glfw"
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            "import sys; from assembler.cli import run; sys.exit(run())",
            "render",
            "Sparrow7",
            "-o",
            str(tmp_path / "x.png"),
        ],
        capture_output=True,
        text=True,
        env=env,
    )
    assert done.returncode == 1
    (line,) = done.stderr.splitlines()
    assert line.startswith("cannot create an OpenGL context for offscreen rendering (MUJOCO_GL=glfw): ")
    assert line.endswith(
        "Set MUJOCO_GL=egl (GPU or Mesa EGL) or MUJOCO_GL=osmesa (software rendering), "
        "or run where a display is available"
    )
    assert not (tmp_path / "x.png").exists()


def test_panda_renders_with_its_mount_and_gripper(tmp_path: Path, sparrow_stage: Stage) -> None:
    pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')
    robot = assembler.assemble("Panda")
    stage = build_stage(robot, WIDTH, HEIGHT)
    (image,) = render_views(stage, ["front"], WIDTH, HEIGHT)
    mask = robot_mask(stage, image, "front")
    assert 0.05 < mask.mean() < 0.7
    assert abs(np.nonzero(mask)[1].mean() / WIDTH - 0.5) < 0.15
    floor_height = stage.data.geom_xpos[stage.model.geom(FLOOR).id][2]
    assert stage.points[:, 2].min() - 0.01 < floor_height < stage.points[:, 2].min()  # just under the mount


BLOCKY_MJCF = """\
<mujoco model="blocky">
  <worldbody>
    <body name="base" pos="0 0 0.1">
      <geom name="base_col" type="box" size="0.1 0.1 0.1" rgba="0.2 0.6 0.2 1"/>
      <body name="link1" pos="0 0 0.2">
        <joint name="j1" axis="0 0 1" range="-3 3"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.3 0 0.3" size="0.04" mass="1"/>
        <body name="right_hand" pos="0.3 0 0.3"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
"""A robot whose geoms are all in group 0 (collision only), as hand-written and URDF-derived MJCF often is."""


@pytest.fixture
def blocky(write) -> Path:  # type: ignore[no-untyped-def]
    write("blocky/blocky.xml", BLOCKY_MJCF)
    return write("blocky/blocky.yaml", "name: Blocky\nmjcf: blocky.xml\n")  # type: ignore[no-any-return]


def part_mask(stage: Stage, robot: RobotModel, image: np.ndarray, view: str, name: str) -> np.ndarray:
    """Pixels where the part ``name`` is: those that change when its geoms alone are hidden."""
    (part,) = [p for p in geoms_by_part(stage.model, (robot, *robot.models)) if p.name == name]
    groups = stage.model.geom_group.copy()
    stage.model.geom_group[list(part.geoms)] = HIDDEN_GROUP
    try:
        (without,) = render_views(stage, [view], image.shape[1], image.shape[0])
    finally:
        stage.model.geom_group[:] = groups
    return np.abs(image.astype(int) - without.astype(int)).max(axis=2) > 24


def test_a_robot_with_only_collision_geoms_is_drawn_and_the_line_says_how(
    blocky: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "blocky.png"
    assert main(["render", str(blocky), "-o", str(target), "--size", f"{WIDTH}x{HEIGHT}"]) == 0
    assert capsys.readouterr().err == (
        f"wrote {target} ({WIDTH}x{HEIGHT}, iso; geom group 0 (collision) for Blocky: it has no visual geoms)\n"
    )
    image = decode_png(target.read_bytes())
    stage = build_stage(assembler.assemble("Blocky"), WIDTH, HEIGHT)
    mask = robot_mask(stage, image, "iso")
    assert 0.05 < mask.mean() < 0.7  # the robot fills the frame: framed on what is drawn
    ys, xs = np.nonzero(mask)
    assert abs(xs.mean() / WIDTH - 0.5) < 0.15 and abs(ys.mean() / HEIGHT - 0.5) < 0.15


def test_a_collision_only_robot_shows_its_collision_geoms_beside_a_gripper_with_visual_ones(
    blocky: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "pair.png"
    argv = ["render", str(blocky), "--gripper", "right=PincerGripper", "-o", str(target), "--size", "320x240"]
    assert main(argv) == 0
    assert capsys.readouterr().err == (
        f"wrote {target} (320x240, iso; geom groups 1, 2; group 0 (collision) for Blocky: it has no visual geoms)\n"
    )
    image = decode_png(target.read_bytes())
    robot = assembler.assemble("Blocky", grippers={"right": "PincerGripper"})
    stage = build_stage(robot, 320, 240)
    assert part_mask(stage, robot, image, "iso", "Blocky").mean() > 0.02
    assert part_mask(stage, robot, image, "iso", "PincerGripper").mean() > 0.002
    # the gripper shows only its visual geoms: every drawn gripper geom was in group 1 or 2
    model, name = robot.get_model(), mujoco.mjtObj.mjOBJ_GEOM
    drawn = [
        mujoco.mj_id2name(stage.model, name, g)
        for g in range(stage.model.ngeom)
        if stage.model.geom_group[g] != HIDDEN_GROUP
    ]
    gripper = [geom for geom in drawn if geom and geom.startswith("gripper0_right_")]
    assert gripper and all(model.geom(geom).group in (1, 2) for geom in gripper)


def test_groups_choose_what_is_drawn(
    sparrow_stage: Stage, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    default, collision = tmp_path / "default.png", tmp_path / "collision.png"
    size = ["--size", f"{WIDTH}x{HEIGHT}", "--views", "side"]
    assert main(["render", "Sparrow7", "-o", str(default), *size]) == 0
    assert main(["render", "Sparrow7", "-o", str(collision), "--groups", "0", *size]) == 0
    assert (
        capsys.readouterr().err.splitlines()[-1]
        == f"wrote {collision} ({WIDTH}x{HEIGHT}, side; geom group 0)"
    )
    first, second = decode_png(default.read_bytes()), decode_png(collision.read_bytes())
    changed = np.abs(first.astype(int) - second.astype(int)).max(axis=2) > 24
    assert changed.mean() > 0.01  # Sparrow7's collision capsules are not its visual meshes


def test_groups_that_draw_nothing_are_an_error_not_an_empty_picture(
    blocky: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "empty.png"
    assert main(["render", str(blocky), "--groups", "3,4", "-o", str(target)]) == 1
    assert capsys.readouterr().err == (
        "nothing to draw: Blocky has no geom in geom groups 3, 4 (its geoms are in geom group 0); "
        "choose the groups to draw with --groups, e.g. --groups 0,1,2\n"
    )
    assert not target.exists()


@pytest.mark.parametrize("value", ["", "6", "1,x", "-1"])
def test_groups_outside_mujocos_six_are_a_usage_error(value: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as caught:
        main(["render", "Sparrow7", "-o", "x.png", f"--groups={value}"])
    assert caught.value.code == 2
    assert capsys.readouterr().err.splitlines()[-1] == (
        f"assembler render: error: argument --groups: expected geom groups 0 to 5 separated by commas, "
        f"e.g. 0,1,2; got '{value}'"
    )


def test_the_cli_offers_the_renderers_views_labels_and_groups() -> None:
    assert tuple(VIEWS) == arguments.VIEWS
    assert set(arguments.LABELS) == set(LABELS)
    assert list(arguments.GEOM_GROUPS) == list(range(mujoco.mjNGROUP))


@pytest.mark.parametrize(
    ("name", "make"),
    [("PincerGripper", assembler.create_gripper), ("RoverBase", assembler.create_base)],
    ids=["gripper", "base"],
)
def test_a_gripper_or_base_spec_renders_alone_as_build_makes_it(
    name: str, make: Callable[[str], PartModel], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    stage = build_stage(make(name), WIDTH, HEIGHT)
    (image,) = render_views(stage, ["iso"], WIDTH, HEIGHT)
    assert robot_mask(stage, image, "iso").mean() > 0.05  # the part fills its picture, framed alone
    out = tmp_path / "part.png"
    assert main(["render", name, "-o", str(out)]) == 0  # was "unknown robot"
    assert out.read_bytes().startswith(b"\x89PNG") and capsys.readouterr().err.startswith(f"wrote {out}")
