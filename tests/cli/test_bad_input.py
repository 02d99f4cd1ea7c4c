"""Bad input, through the command line: every row gets its exact message, exit code 1, no file.

Each row is a spec's bytes and the lines ``assembler build`` prints (``{spec}`` is the spec's
path). Bad numbers, wrong shapes, bad encodings and resource bombs all end here as one readable
line, never a traceback and never a crash later inside MuJoCo.
"""

from __future__ import annotations

import os
from pathlib import Path

import mujoco
import pytest

from assembler.cli import main
from assembler.files.limits import MAX_SPEC_BYTES, MAX_YAML_DEPTH, MAX_YAML_ITEMS, MAX_YAML_VALUES
from assembler.files.writing import shown
from tests.conftest import MOBILE_MJCF, TWO_LINK_MJCF
from tests.urdf.fixtures import ARM_URDF, write_package

ARM = b"name: Arm\nmjcf: twolink.xml\n"
BASE = b"kind: base\nname: Cart\ntype: mobile\nmjcf: mobile.xml\n"
ONE_PER_JOINT = "expected a non-negative number, a list of them (one per joint), a mapping 'inverse_index: <scale>' or null"

LAUGHS = b"".join(
    [ARM, b"a: &a [x, x, x, x, x, x, x, x, x, x]\n"]
    + [
        f"{b}: &{b} [{', '.join(['*' + a] * 10)}]\n".encode()
        for a, b in zip("abcdefg", "bcdefgh", strict=True)
    ]
)

# One row per line, so the table reads as a table.
# fmt: off
CASES = [
    # numbers
    pytest.param(ARM + b"init_qpos: [0, .nan]\n", ["{spec}:3:16: init_qpos[1]: Input should be a finite number"], id="nan"),
    pytest.param(ARM + b"top_offset: [0, 0, .inf]\n", ["{spec}:3:20: top_offset[2]: Input should be a finite number"], id="infinity"),
    pytest.param(ARM + b"horizontal_radius: 1.0e+999\n", ["{spec}:3:20: horizontal_radius: Input should be a finite number"], id="overflow-to-infinity"),
    pytest.param(ARM + b"joint_defaults: {damping: -.inf}\n", [f"{{spec}}:3:27: joint_defaults.damping: {ONE_PER_JOINT}, got -inf"], id="negative-infinity-rule"),
    pytest.param(ARM + b"joints:\n  - {match: shoulder, damping: -1}\n", ["{spec}:4:32: joints[0].damping: Input should be greater than or equal to 0"], id="negative-damping"),
    pytest.param(ARM + b"horizontal_radius: -0.5\n", ["{spec}:3:20: horizontal_radius: Input should be greater than or equal to 0"], id="negative-radius"),
    pytest.param(ARM + b"horizontal_radius: " + b"1" * 5000 + b"\n", ["{spec}:3:20: horizontal_radius: YAML: cannot read '1111111111111111111111111111111111111...' as int"], id="integer-of-5000-digits"),
    pytest.param(ARM + b"horizontal_radius: !!float abc\n", ["{spec}:3:20: horizontal_radius: YAML: cannot read 'abc' as float"], id="explicit-float-tag-on-text"),
    pytest.param(ARM + b"remove_free_joint: !!bool maybe\n", ["{spec}:3:20: remove_free_joint: YAML: cannot read 'maybe' as bool"], id="explicit-bool-tag-on-text"),
    # booleans are not numbers (pydantic read true as 1.0)
    pytest.param(ARM + b"joints:\n  - {match: shoulder, damping: true}\n", ["{spec}:4:32: joints[0].damping: expected a number, got true"], id="true-for-a-number"),
    pytest.param(ARM + b"joint_defaults: {damping: true}\n", [f"{{spec}}:3:27: joint_defaults.damping: {ONE_PER_JOINT}, got true"], id="true-for-a-rule"),
    pytest.param(ARM + b"joint_defaults: {armature: [0.1, false]}\n", [f"{{spec}}:3:28: joint_defaults.armature: {ONE_PER_JOINT}, got [0.1, false]"], id="false-in-a-rule-list"),
    pytest.param(ARM + b"joint_defaults: {damping: {inverse_index: true}}\n", [f"{{spec}}:3:27: joint_defaults.damping: {ONE_PER_JOINT}, got {{{{'inverse_index': True}}}}"], id="true-for-the-inverse-index"),
    pytest.param(ARM + b"top_offset: [0, 0, false]\n", ["{spec}:3:20: top_offset[2]: expected a number, got false"], id="false-in-a-vector"),
    pytest.param(ARM + b"init_qpos: [true, 0]\n", ["{spec}:3:13: init_qpos[0]: expected a number, got true"], id="true-in-a-pose"),
    pytest.param(ARM + b"horizontal_radius: yes\n", ["{spec}:3:20: horizontal_radius: expected a number, got true"], id="yes-for-a-number"),
    # control characters written as YAML escapes (YAML refuses them written out)
    pytest.param(b'name: "Arm\\x07"\nmjcf: twolink.xml\n', ["{spec}:1:7: name: YAML: character #x0007 (written as an escape) is not allowed in text; remove it"], id="bell-in-a-name"),
    pytest.param(ARM + b'description: "ring \\a"\n', ["{spec}:3:14: description: YAML: character #x0007 (written as an escape) is not allowed in text; remove it"], id="bell-in-a-description"),
    pytest.param(ARM + b'joints:\n  - {match: "shoul\\x1bder"}\n', ["{spec}:4:13: joints[0].match: YAML: character #x001b (written as an escape) is not allowed in text; remove it"], id="escape-in-a-pattern"),
    pytest.param(ARM + b'"init\\x01qpos": [0, 0]\n', ["{spec}:3:1: YAML: character #x0001 (written as an escape) is not allowed in text; remove it"], id="control-character-in-a-key"),
    pytest.param(ARM + b'description: "\\u0085\\u009b"\n', ["{spec}:3:14: description: YAML: character #x009b (written as an escape) is not allowed in text; remove it"], id="c1-control-character"),
    # ranges
    pytest.param(BASE + b"added_joints:\n  - {name: x, type: slide, axis: [1, 0, 0], range: [1, -1]}\n", ["{spec}:6:52: added_joints[0].range: expected min < max, got [1.0, -1.0]"], id="range-min-above-max"),
    pytest.param(BASE + b"added_joints:\n  - name: x\n    type: slide\n    axis: [1, 0, 0]\n    actuator: {name: ax, kv: 10, ctrlrange: [0.5, 0.5]}\n", ["{spec}:9:45: added_joints[0].actuator.ctrlrange: expected min < max, got [0.5, 0.5]"], id="empty-ctrlrange"),
    pytest.param(BASE + b"added_joints:\n  - name: x\n    type: slide\n    axis: [1, 0, 0]\n    actuator: {name: ax, kv: 10, ctrlrange: [-1, 1], forcerange: [0, .nan]}\n", ["{spec}:9:70: added_joints[0].actuator.forcerange[1]: Input should be a finite number"], id="nan-in-forcerange"),
    # vector sizes
    pytest.param(ARM + b"top_offset: [0, 0]\n", ["{spec}:3:13: top_offset: expected 3 values, got 2"], id="vector-too-short"),
    pytest.param(ARM + b"top_offset: [0, 0, 0, 0]\n", ["{spec}:3:13: top_offset: Tuple should have at most 3 items after validation, not 4"], id="vector-too-long"),
    pytest.param(ARM + b"init_qpos: [0, 0, 0]\n", ["{spec}:3:12: init_qpos: expected 2 values (one per joint: shoulder, elbow), got 3"], id="one-value-per-joint"),
    pytest.param(ARM + b"top_offset: 1.0\n", ["{spec}:3:13: top_offset: Input should be a valid tuple"], id="number-for-vector"),
    # document shape
    pytest.param(b"", ["{spec}:1:1: the file is empty; a spec is a YAML mapping"], id="empty-file"),
    pytest.param(b"# only a comment\n\n", ["{spec}:1:1: the file is empty; a spec is a YAML mapping"], id="comments-only"),
    pytest.param(b"- name: Arm\n- mjcf: twolink.xml\n", ["{spec}:1:1: a spec must be a YAML mapping (key: value lines)"], id="list-document"),
    pytest.param(b"just some text\n", ["{spec}:1:1: a spec must be a YAML mapping (key: value lines)"], id="text-document"),
    pytest.param(ARM + b"---\nname: B\n", ["{spec}:3:1: YAML syntax error: expected a single document in the stream but found another document"], id="two-documents"),
    pytest.param(ARM + b"1: x\n", ["{spec}:3:1: keys must be text, got int"], id="number-key"),
    pytest.param(ARM + b"init_qpos: &x [*x]\n", ["{spec}:3:12: init_qpos[0]: a recursive alias (an anchor used inside itself) has no value; write the values out"], id="recursive-alias"),
    pytest.param(ARM + b"description: 2024-01-01\n", ["{spec}:3:14: description: YAML tag 'tag:yaml.org,2002:timestamp' is not allowed; specs are plain data"], id="date"),
    pytest.param(b"name: !!python/object/apply:os.system [touch pwned]\nmjcf: twolink.xml\n", ["{spec}:1:7: name: YAML tag 'tag:yaml.org,2002:python/object/apply:os.system' is not allowed; specs are plain data"], id="python-tag"),
    pytest.param(b"d: &d {damping: 0.1}\n" + ARM + b"joint_defaults:\n  <<: *d\n", ["{spec}:5:3: joint_defaults: YAML merge keys ('<<') are not supported; write the keys out"], id="merge-key"),
    # encodings
    pytest.param(ARM + b"description: caf\xe9\n", ["{spec}: the file is not UTF-8 text (byte 44); save it as UTF-8"], id="latin-1"),
    pytest.param(ARM.decode().encode("utf-16"), ["{spec}: the file is not UTF-8 text (byte 0); save it as UTF-8"], id="utf-16"),
    pytest.param(ARM + b"description: a\x00b\n", ["{spec}:3:15: YAML: character #x0000 is not allowed in YAML text"], id="nul-byte"),
    pytest.param(b"name: Arm\r\nmjcf: twolink.xml\r\ninit_qpos: [0.1, x]\r\n", ["{spec}:3:18: init_qpos[1]: Input should be a valid number, unable to parse string as a number"], id="crlf-positions"),
    # resource bombs
    pytest.param(LAUGHS, [f"{{spec}}:3:8: e[7][8][8][8][0]: the values in the document, aliases expanded, exceed the limit of {MAX_YAML_VALUES}; each alias (*name) repeats all its anchor names: write the values out instead"], id="billion-laughs"),
    pytest.param(ARM + b"init_qpos: " + b"[" * 100 + b"]" * 100 + b"\n", [f"{{spec}}:3:{12 + MAX_YAML_DEPTH - 1}: nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels; a spec nests a few levels deep"], id="deep-lists"),
    pytest.param(ARM + b"joint_defaults: " + b"{a: " * 100 + b"1" + b"}" * 100 + b"\n", [f"{{spec}}:3:{17 + 4 * (MAX_YAML_DEPTH - 2) + 1}: nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels; a spec nests a few levels deep"], id="deep-mappings"),
    pytest.param(ARM + b"init_qpos: [" + b"0, " * MAX_YAML_ITEMS + b"0]\n", [f"{{spec}}:3:12: init_qpos: a list of {MAX_YAML_ITEMS + 1} items exceeds the limit of {MAX_YAML_ITEMS} items"], id="huge-list"),
    pytest.param(ARM + b"description: " + b"x" * MAX_SPEC_BYTES + b"\n", [f"{{spec}}: the file's size exceeds the limit of {MAX_SPEC_BYTES} bytes for a spec file"], id="huge-file"),
    # what MuJoCo itself refuses is reported, not crashed on
    pytest.param(b"name: Arm\nmjcf: negative_mass.xml\n", ["{spec}:2:7: mjcf: {folder}/negative_mass.xml:23: MuJoCo refuses it: mass, inertia or density are negative in geom (element 'link2_col'); correct the file (a spec can declare a repair: mjcf_fixes)"], id="negative-mass-in-mjcf"),
    pytest.param(b"name: Arm\nmjcf: missing.xml\n", ["{spec}:2:7: mjcf: MJCF file not found: {folder}/missing.xml"], id="missing-mjcf"),
    # paths the file system refuses (found by the 10,000-case fuzz run: a traceback before)
    pytest.param(ARM + b"extends: " + b"x" * 300 + b".yaml\n", ["{spec}:3:10: extends: parent spec file not found: {folder}/" + "x" * 300 + ".yaml"], id="parent-file-name-too-long"),
]
# fmt: on


def _folder(tmp_path: Path) -> Path:
    folder = tmp_path / "specs"
    folder.mkdir()
    (folder / "twolink.xml").write_text(TWO_LINK_MJCF)
    (folder / "mobile.xml").write_text(MOBILE_MJCF)
    (folder / "negative_mass.xml").write_text(TWO_LINK_MJCF.replace('mass="0.5"', 'mass="-0.5"'))
    return folder


@pytest.mark.parametrize(("content", "expected"), CASES)
def test_bad_input_gets_its_exact_message_and_writes_nothing(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], content: bytes, expected: list[str]
) -> None:
    folder = _folder(tmp_path)
    spec = folder / "bad.yaml"
    spec.write_bytes(content)
    out = tmp_path / "out.xml"
    code = main(["build", str(spec), "-o", str(out)])
    captured = capsys.readouterr()
    assert (code, captured.err.splitlines()) == (
        1,
        [line.format(spec=spec, folder=folder) for line in expected],
    )
    assert captured.out == ""
    assert not out.exists()


def test_a_robot_name_too_long_for_a_file_name_is_an_unknown_robot(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["build", "x" * 300]) == 1
    (line,) = capsys.readouterr().err.splitlines()
    assert line.startswith(f"unknown robot '{'x' * 300}'")


def test_a_byte_order_mark_and_windows_line_endings_just_work(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    spec = _folder(tmp_path) / "arm.yaml"
    spec.write_bytes(b"\xef\xbb\xbfname: Arm\r\nmjcf: twolink.xml\r\ninit_qpos: [0.1, 0.2]\r\n")
    out = tmp_path / "arm.xml"
    assert main(["build", str(spec), "-o", str(out)]) == 0
    assert capsys.readouterr().err == f"wrote {out}\n"
    model = mujoco.MjModel.from_xml_path(str(out))
    assert model.key("home").qpos.tolist() == [0.1, 0.2]


def test_a_list_as_name_with_an_unknown_parent_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Found by the long fuzz run: the name was hashed while listing the known parents."""
    spec = _folder(tmp_path) / "bad.yaml"
    spec.write_text("name: []\nextends: Sparow7\nmjcf: twolink.xml\n")
    assert main(["build", str(spec)]) == 1
    (line,) = capsys.readouterr().err.splitlines()
    assert line == f"{spec}:2:10: extends: unknown robot spec 'Sparow7'. Did you mean 'Sparrow7'?"


@pytest.mark.parametrize("command", ["scene", "experiment"])
def test_scene_and_experiment_files_get_the_spec_file_rules(
    command: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    missing, latin1, outside = tmp_path / "missing.yaml", tmp_path / "latin1.yaml", tmp_path / "outside.yaml"
    latin1.write_bytes("name: caf\xe9\n".encode("latin-1"))
    outside.write_text(f"kind: {command}\nname: Outside\nrobots:\n  - robot: ../elsewhere/arm.yaml\n")
    (tmp_path.parent / "elsewhere").mkdir(exist_ok=True)
    (tmp_path.parent / "elsewhere" / "arm.yaml").write_text("name: Arm\nmjcf: arm.xml\n")
    for file, expected in [
        (missing, "cannot read the file: No such file or directory"),
        (latin1, "the file is not UTF-8 text (byte 9); save it as UTF-8"),
        (
            outside,
            "robot spec " + str(tmp_path.parent / "elsewhere" / "arm.yaml") + " is outside the folders",
        ),
    ]:
        assert main([command, str(file)]) == 1
        err = capsys.readouterr().err
        assert expected in err and "Traceback" not in err, err


FIFO = "it is a FIFO (named pipe), not a regular file"
FOLDER = "it is a folder, not a file"
DEVICE = "it is a character device, not a regular file"
NEW_HINT = "; give an MJCF (.xml) or URDF (.urdf) file"
MESH_MJCF = TWO_LINK_MJCF.replace("<worldbody>", '<asset><mesh name="x" file="x.obj"/></asset><worldbody>')


def _fifo(path: Path) -> None:
    os.mkfifo(path)


def _folder_at(path: Path) -> None:
    path.mkdir()


def _device(path: Path) -> None:
    path.symlink_to(os.devnull)


KINDS = {"fifo": (_fifo, FIFO), "folder": (_folder_at, FOLDER), "device": (_device, DEVICE)}

# The kind of thing put at x.*, the command, and the line it prints.
# fmt: off
NOT_FILES = [
    ("fifo", ["build", "x.yaml"], "x.yaml: cannot read the file: {kind}"),
    ("device", ["build", "x.yaml"], "x.yaml: cannot read the file: {kind}"),
    ("fifo", ["build", "mjcf.yaml"], "mjcf.yaml:2:7: mjcf: x.xml: {kind}"),
    ("folder", ["build", "mjcf.yaml"], "mjcf.yaml:2:7: mjcf: x.xml: {kind}"),
    ("fifo", ["build", "urdf.yaml"], "urdf.yaml:2:7: urdf: x.urdf: {kind}"),
    ("folder", ["build", "urdf.yaml"], "urdf.yaml:2:7: urdf: x.urdf: {kind}"),
    *[(kind, ["diff", "x.yaml", "Sparrow7"], "x.yaml: {kind}; give one spec file") for kind in KINDS],
    ("fifo", ["build", "include.yaml"], "include.yaml:2:7: mjcf: include.xml: <include> file x.xml: {kind}"),
    ("folder", ["build", "include.yaml"], "include.yaml:2:7: mjcf: include.xml: <include> file x.xml: {kind}"),
    ("fifo", ["build", "mesh.yaml"], "mesh.yaml:2:7: mjcf: mesh.xml: asset file x.obj: {kind}"),
    ("folder", ["build", "mesh.yaml"], "mesh.yaml:2:7: mjcf: mesh.xml: asset file x.obj: {kind}"),
    *[(kind, ["new", f"x.{suffix}"], f"x.{suffix}: {{kind}}{NEW_HINT}") for kind in KINDS for suffix in ("xml", "urdf")],
    *[(kind, [command, "x.yaml"], "x.yaml: cannot read the file: {kind}") for kind in KINDS for command in ("scene", "experiment", "validate") if (command, kind) != ("validate", "folder")],  # validate reads a folder's specs
    ("fifo", ["scene", "scene.yaml"], "scene.yaml:4:5: robots[0]: robot spec x.yaml: {kind}; name the robot's spec file"),
    ("folder", ["scene", "scene.yaml"], "scene.yaml:4:5: robots[0]: robot spec x.yaml: {kind}; name the robot's spec file"),
]
# fmt: on


@pytest.mark.parametrize(
    ("kind", "words", "expected"), NOT_FILES, ids=[f"{k}-for-{w[0]}-{w[1]}" for k, w, _ in NOT_FILES]
)
def test_a_fifo_folder_or_device_for_a_file_says_what_it_is(
    kind: str,
    words: list[str],
    expected: str,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """Before, a FIFO hung the command, a folder or a device was 'not found' (or a traceback)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "mjcf.yaml").write_text("name: Arm\nmjcf: x.xml\n")
    (tmp_path / "urdf.yaml").write_text("name: Arm\nurdf: x.urdf\n")
    (tmp_path / "mesh.yaml").write_text("name: Arm\nmjcf: mesh.xml\n")
    (tmp_path / "mesh.xml").write_text(MESH_MJCF)
    (tmp_path / "include.yaml").write_text("name: Arm\nmjcf: include.xml\n")
    (tmp_path / "include.xml").write_text(
        TWO_LINK_MJCF.replace("</mujoco>", '<include file="x.xml"/></mujoco>')
    )
    (tmp_path / "scene.yaml").write_text("kind: scene\nname: S\nrobots:\n  - robot: x.yaml\n")
    make, text = KINDS[kind]
    for target in ["x.xml", "x.urdf", "x.obj", "x.yaml"]:
        make(tmp_path / target)
    assert main(words) == 1
    assert capsys.readouterr().err == expected.format(kind=text) + "\n"


LONG = "x" * 300
"""A file name longer than any file system allows (255 bytes)."""

WRITE = "cannot write {out}: File name too long"
"""The line of an output whose name is too long ({out}: the name as messages cut it)."""

# fmt: off
LONG_NAMES = [
    (["new", "twolink.xml", "-o", f"{LONG}.yaml"], WRITE),
    (["new", "twolink.xml", "-o", f"{LONG}/arm.yaml"], WRITE),
    (["build", "arm.yaml", "-o", f"{LONG}.xml"], WRITE),
    (["build", "arm.yaml", "--bundle", LONG], WRITE),  # {out}: its assets folder, made first
    (["scene", "scene.yaml", "-o", f"{LONG}.xml"], WRITE),
    (["experiment", "experiment.yaml", "-o", f"{LONG}.xml"], WRITE),
    (["render", "arm.yaml", "--size", "32x24", "-o", f"{LONG}.png"], WRITE),
    (["variants", "arm.yaml", "--grid", "joint_defaults.damping=0.1", "-o", LONG], WRITE),
    (["new", f"{LONG}.xml"], f"{LONG}.xml: no such file; give an MJCF (.xml) or URDF (.urdf) file"),
    (["build", f"{LONG}.yaml"], f"no such file or folder: {LONG}.yaml"),
    (["scene", f"{LONG}.yaml"], f"{LONG}.yaml: cannot read the file: File name too long"),
]
# fmt: on


@pytest.mark.parametrize(("words", "expected"), LONG_NAMES, ids=[" ".join(w)[:40] for w, _ in LONG_NAMES])
def test_a_file_name_too_long_is_one_line(
    words: list[str],
    expected: str,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """Found by the hostile-input battery: ``new -o`` with a 300-character name was a traceback."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "twolink.xml").write_text(TWO_LINK_MJCF)
    (tmp_path / "arm.yaml").write_text("name: Arm\nmjcf: twolink.xml\n")
    for kind in ("scene", "experiment"):
        (tmp_path / f"{kind}.yaml").write_text(f"kind: {kind}\nname: S\nrobots:\n  - robot: arm.yaml\n")
    assert main(words) == 1
    line = expected.format(out=shown(Path(words[-1] + ("/assets" if "--bundle" in words else ""))))
    assert capsys.readouterr().err == line + "\n"


SET = "--set joint_defaults.damping"

# fmt: off
SET_VALUES = [
    ("[" * 2000 + "]" * 2000, f"{SET}: nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels; a spec nests a few levels deep"),
    ("{a: " * 200 + "1" + "}" * 200, f"{SET}: nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels; a spec nests a few levels deep"),
    ("&a [" + "*a, " * 3 + "1]", f"{SET}: a recursive alias (an anchor used inside itself) has no value; write the values out"),
    ('"\\x07"', f"{SET}: YAML: character #x0007 (written as an escape) is not allowed in text; remove it"),
    ("2024-01-01", f"{SET}: YAML tag 'tag:yaml.org,2002:timestamp' is not allowed; specs are plain data"),
    ("[1, 2", f"{SET}: YAML syntax error: expected ',' or ']', but got '<stream end>'"),
    ("true", f"{SET}: {ONE_PER_JOINT}, got true"),
]
# fmt: on


@pytest.mark.parametrize(("value", "expected"), SET_VALUES, ids=[v[:20] for v, _ in SET_VALUES])
def test_a_set_value_is_read_as_a_spec_files_values_are(
    value: str, expected: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Found by the hostile-input battery: a deeply nested --set value was a RecursionError."""
    spec = _folder(tmp_path) / "arm.yaml"
    spec.write_bytes(ARM)
    assert main(["build", str(spec), "--set", f"joint_defaults.damping={value}"]) == 1
    assert capsys.readouterr().err == expected + "\n"


@pytest.mark.parametrize("kind", ["fifo", "folder"])
@pytest.mark.parametrize(("mesh", "line"), [("cube.stl", 6), ("cube.dae", 10)])
def test_a_urdf_mesh_that_is_no_file_says_what_it_is(
    kind: str,
    mesh: str,
    line: int,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
) -> None:
    """Before, 'no file ... in package' (a FIFO or a folder is there)."""
    monkeypatch.chdir(tmp_path)
    write_package(tmp_path / "ros", urdf=ARM_URDF)
    (tmp_path / "arm.yaml").write_text(
        "name: Arm\nurdf: ros/my_arm/urdf/my_arm.urdf\neef_bodies: {right: tool}\n"
    )
    (tmp_path / "ros/my_arm/meshes" / mesh).unlink()
    make, text = KINDS[kind]
    make(tmp_path / "ros/my_arm/meshes" / mesh)
    assert main(["build", "arm.yaml", "--no-base"]) == 1
    assert capsys.readouterr().err == (
        f"arm.yaml:2:7: urdf: ros/my_arm/urdf/my_arm.urdf:{line}: mesh package://my_arm/meshes/{mesh}: "
        f"ros/my_arm/meshes/{mesh}: {text}\n"
    )
