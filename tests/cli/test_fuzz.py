"""Fuzzing: mutated shipped specs and specs drawn from the schema, built through the command line.

Every run must end in a written, loadable model (exit 0) or in one readable line per problem
(exit 1): never another exception, never a hang (hypothesis' deadline), never a partial or
temporary file in the output folder. CI runs 200 cases; ``FUZZ_EXAMPLES=10000 pytest
tests/cli/test_fuzz.py`` is the long run SECURITY.md reports.
"""

from __future__ import annotations

import os
import re
import tempfile
from collections.abc import Iterator
from datetime import timedelta
from pathlib import Path

import mujoco
import pytest
import yaml
from hypothesis import HealthCheck, currently_in_test_context, event, given, settings
from hypothesis import strategies as st
from hypothesis.configuration import set_hypothesis_home_dir

from assembler.cli import main
from assembler.files.paths import shipped_specs_dir
from assembler.models.motor_table import MOTORS
from assembler.registry.lookup import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS
from assembler.spec.schema import RobotSpec
from assembler.urdf.packages import package_folders

set_hypothesis_home_dir(Path(tempfile.gettempdir()) / "robot-assembler-hypothesis")
"""Hypothesis keeps caches (e.g. of Unicode data) there, not in a .hypothesis folder in the repository."""

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "200"))
"""Cases per test; the long run sets FUZZ_EXAMPLES=10000 (and draws new cases each time)."""

FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=timedelta(seconds=60),  # a hang, not a slow machine: a build takes well under a second
    derandomize="FUZZ_EXAMPLES" not in os.environ,  # CI: the same cases each run, so no flaky failures
    database=None,  # no .hypothesis folder in the repository
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture],
)


MJCF_LINE = re.compile(r"(?m)^mjcf: (.*)$")


def _shipped_texts() -> list[str]:
    """The shipped specs' text, named Fuzzed, with ``mjcf`` made absolute (the shipped assets)."""
    texts = []
    for path in sorted(shipped_specs_dir().glob("**/*.yaml")):
        if "robosuite" in path.parts:
            continue  # robosuite's meshes make each build slow; the shape of the specs is the same
        if "urdf" in path.parts and not package_folders("example-robot-data"):
            continue  # their URDFs come with the urdf extra; without it every build stops at that line
        text = path.read_text()
        text = re.sub(r"(?m)^name: .*$", "name: Fuzzed", text)
        absolute = f"mjcf: {(path.parent / m.group(1)).resolve()}" if (m := MJCF_LINE.search(text)) else ""
        text = MJCF_LINE.sub(absolute, text)
        texts.append(text)
    return texts


def _loads(text: str) -> bool:
    try:
        yaml.safe_load(f"x: {text}")
    except (yaml.YAMLError, ValueError, KeyError, TypeError):  # e.g. "!!int x"
        return False
    return True


SHIPPED = _shipped_texts()
SPARROW7_MJCF = re.findall(r"(?m)^mjcf: (.*sparrow7\.xml)$", "\n".join(SHIPPED))[0]

NASTY_VALUES = [
    "", "~", ".nan", ".inf", "-.inf", "-1", "0", "-0.0", "1e308", "1.0e+999", "yes", "0x1F", "1_000",
    "2024-01-01", "!!binary aGk=", "!!python/name:os.system", "!!python/object/apply:os.system [id]",
    "&a x", "*a", "*undefined", "<<", "'", '"', "[", "{", "|", ">", "---", "...", "? x", "- x", "!x",
    "!!int x", "!!float x", "!!bool x", "!!map x", "!!seq x", "1" * 5000, "[" * 80 + "]" * 80,
    "{a: " * 70 + "1" + "}" * 70, "[x, *a]", "package://robosuite/../../../../etc/hostname",
    "package://os.path/x.xml", "package://no_such_package/x.xml", "/etc/passwd", "../../../../etc/hostname",
    "-0.16 - table_length / 2", "__import__('os')", "(" * 120 + "1" + ")" * 120, "table_length / 0",
    "1 +", "joint[", "*", "[0, 0, 0]", "[.nan, 0, 0]", "[0, 0]", "[0, 0, 0, 0]", "{inverse_index: 0}",
    "{inverse_index: -1}", "[1, -1]", "[]", "{}", "[1, 2, 3, 4, 5, 6, 7]", "{right: null}",
    "{right: NoSuchGripper}", "{left: PincerGripper}", "NoSuchBase", "QuadrupedBase", "RoverBase",
    "bimanual", "humanoid", "legged_manipulator", "Sparrow7", "Fuzzed", "specs/biped.yaml",
]  # fmt: skip
"""Values that have broken parsers before: special floats, tags, anchors, YAML syntax, bombs,
paths that leave their folder, expressions that are not arithmetic, names that do not exist."""

NAMES = [
    "none", "Pedestal", "QuadrupedBase", "RoverBase", "SiteOnlyBase", "PincerGripper", "TriHand",
    "BareFlange", "NoSuch", "joint1", "joint*", "joint[", "*", "right_hand", "left_hand", "support",
    "eef", "grip_site", "mount", "mobile", "legged", "null", "humanoid", "manipulator", "bimanual",
    "single", "right", "left", "robot", "base", "gripper", "Fuzzed", "Sparrow7", "Biped",
]  # fmt: skip
"""Names that exist somewhere (parts, joints, bodies, choices) or almost do."""

SAFE_NASTY = [text for text in NASTY_VALUES if _loads(text)]
"""The nasty values that are YAML on their own, to put into a parsed document."""

json_like = st.recursive(
    st.none() | st.booleans() | st.floats() | st.integers() | st.text(max_size=12),
    lambda inner: st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=8), inner, max_size=4),
    max_leaves=12,
)
values = st.one_of(
    st.sampled_from(NASTY_VALUES),
    st.text(max_size=20),
    st.floats().map(repr),
    st.integers().map(str),
    json_like.map(lambda v: yaml.safe_dump(v, default_flow_style=True).strip().removesuffix("...").strip()),
)
keys = st.sampled_from(sorted({*RobotSpec.model_fields, "kind", "type", "match", "damping"})) | st.text(
    max_size=10
)


@st.composite
def text_mutation(draw: st.DrawFn) -> bytes:
    """A shipped spec's text with one to three line edits: deleted, duplicated, swapped or
    re-indented lines, values or keys replaced; sometimes random bytes or a cut-off end."""
    lines = draw(st.sampled_from(SHIPPED)).splitlines()
    for _ in range(draw(st.integers(1, 3))):
        at = draw(st.integers(0, len(lines) - 1)) if lines else 0
        edit = draw(st.sampled_from(["delete", "duplicate", "swap", "indent", "value", "key", "insert"]))
        if edit == "insert" or not lines:
            lines.insert(at, f"{draw(keys)}: {draw(values)}")
        elif edit == "delete":
            del lines[at]
        elif edit == "duplicate":
            lines.insert(at, lines[at])
        elif edit == "swap":
            other = draw(st.integers(0, len(lines) - 1))
            lines[at], lines[other] = lines[other], lines[at]
        elif edit == "indent":
            lines[at] = " " * draw(st.integers(0, 6)) + lines[at].lstrip()
        elif edit == "value":
            key, _, _ = lines[at].partition(":")
            lines[at] = f"{key}: {draw(values)}"
        else:
            _, _, value = lines[at].partition(":")
            lines[at] = f"{draw(keys)}:{value}"
    data = "\n".join(lines).encode()
    if draw(st.integers(0, 7)) == 0:
        at = draw(st.integers(0, len(data)))
        data = data[:at] + draw(st.binary(min_size=1, max_size=6)) + data[at:]
    if draw(st.integers(0, 9)) == 0:
        data = data[: len(data) * draw(st.integers(3, 9)) // 10]
    return data


def _places(data: object, path: tuple[object, ...] = ()) -> Iterator[tuple[object, ...]]:
    """Every path to a value inside ``data`` (mapping keys and list indices)."""
    yield path
    items = data.items() if isinstance(data, dict) else enumerate(data) if isinstance(data, list) else ()
    for key, value in items:
        yield from _places(value, (*path, key))


def _typed_change(draw: st.DrawFn, current: object) -> object:
    """A value of the same shape: what a plausible but wrong edit looks like."""
    if isinstance(current, bool):
        return not current
    if isinstance(current, (int, float)):
        factor = draw(st.sampled_from([-1.0, 0.0, 0.5, 2.0, 1e6, 1e-6, float("nan"), float("inf")]))
        return draw(st.sampled_from([current * factor, draw(st.floats(-10, 10))]))
    if isinstance(current, str):
        return draw(st.sampled_from(NAMES) | st.text(max_size=12))
    if isinstance(current, list):
        return draw(st.sampled_from([current[:-1], current + current[:1], [], current[::-1]]))
    return current


@st.composite
def tree_mutation(draw: st.DrawFn) -> bytes:
    """A shipped spec parsed, with one or two values changed (mostly keeping their shape), removed,
    or replaced by anything, written back as YAML: these get past the parser into the schema,
    the assembly, MuJoCo and the writer."""
    document = yaml.safe_load(draw(st.sampled_from(SHIPPED)))
    for _ in range(draw(st.integers(1, 2))):
        path = draw(st.sampled_from(list(_places(document))[1:]))
        parent = document
        for part in path[:-1]:
            parent = parent[part]
        edit = draw(st.sampled_from(["typed", "typed", "typed", "typed", "remove", "any", "nasty"]))
        if edit == "remove":
            del parent[path[-1]]
        elif edit == "typed":
            parent[path[-1]] = _typed_change(draw, parent[path[-1]])
        elif edit == "nasty":
            parent[path[-1]] = yaml.safe_load(f"x: {draw(st.sampled_from(SAFE_NASTY))}")["x"]
        else:
            parent[path[-1]] = draw(json_like)
    return yaml.safe_dump(document, sort_keys=False).encode()


mutated_spec = st.one_of(text_mutation(), tree_mutation())


@st.composite
def schema_spec(draw: st.DrawFn) -> bytes:
    """A robot spec drawn from the schema's fields, each with a value of any shape."""
    document: dict[str, object] = {"name": "Fuzzed", "mjcf": SPARROW7_MJCF}
    for field in draw(st.lists(st.sampled_from(sorted(RobotSpec.model_fields)), max_size=5, unique=True)):
        document[field] = draw(json_like)
    return yaml.safe_dump(document).encode()


PATH_STRINGS = [
    '"a\\0b.yaml"', '"\\0"', "'" + "x" * 300 + ".yaml'", "'" + "d/" * 2100 + "x.yaml'", "../../../etc/passwd.yaml",
    "/etc/hostname", "/", ".", "..", "./", "spec.yaml", "./spec.yaml", "sub/../spec.yaml", "'a b.yaml'",
    "'\u00e9t\u00e9.yaml'", "package://robosuite/../x.yaml", "package://x/y.yaml", "'~/x.yaml'", "'x.yaml\n'",
    "x.yml", "'*'", "'[x]'", "'file:///etc/passwd'", "'C:\\x.yaml'",
]  # fmt: skip
"""Path strings that have broken path handling before, written as YAML scalars."""


@st.composite
def extends_folder(draw: st.DrawFn) -> dict[str, bytes]:
    """A folder of 1 to 6 specs extending one another: by file, by name, in cycles of any length,
    through mutated path strings; ``spec.yaml`` is the one built."""
    count = draw(st.integers(1, 6))
    names = [f"s{index}.yaml" for index in range(count)]
    files: dict[str, bytes] = {}
    for index, file in enumerate(["spec.yaml", *names][:count]):
        lines = [f"name: Fuzzed{index}"]
        if index == count - 1 or draw(st.booleans()):
            mjcf = draw(st.sampled_from([SPARROW7_MJCF, *PATH_STRINGS]))
            lines.append(f"mjcf: {mjcf}")
        target = draw(st.sampled_from(["next", "first", "self", "name", "registered", "missing", "path"]))
        if target == "next" and index + 1 < count:
            lines.append(f"extends: {names[index]}")
        elif target == "first":
            lines.append("extends: spec.yaml")
        elif target == "self":
            lines.append(f"extends: {file}")
        elif target == "name":
            lines.append(f"extends: Fuzzed{draw(st.integers(0, count))}")
        elif target == "registered":
            lines.append(f"extends: {draw(st.sampled_from(NAMES))}")
        elif target == "missing":
            lines.append("extends: no/such/spec.yaml")
        elif target == "path":
            lines.append(f"extends: {draw(st.sampled_from(PATH_STRINGS))}")
        files[file] = ("\n".join(lines) + "\n").encode()
    return files


@pytest.fixture
def isolated(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A working folder (MuJoCo may write a log there) and a cache of its own."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "cache"))
    # a small bound, so that eviction runs between the builds of one process: every part of the one
    # store counts, and a converted mesh one build has just been handed must not be the first to go
    monkeypatch.setenv("ASSEMBLER_CACHE_MAX_BYTES", "50M")
    yield tmp_path


_counter = iter(range(10**9))


def _run_case(
    folder: Path, content: bytes, capsys: pytest.CaptureFixture[str], others: dict[str, bytes] | None = None
) -> int:
    """Build (or, for a base or gripper, validate and compile) one spec (with ``others`` beside it);
    check what the user gets."""
    case = folder / f"case{next(_counter)}"
    case.mkdir()
    for name, text in (others or {}).items():
        (case / name).write_bytes(text)
    spec = case / "spec.yaml"
    spec.write_bytes(content)
    out = case / "out"
    out.mkdir()
    robot = re.search(rb"(?m)^kind: *(base|gripper|motor)", content) is None  # the others: validate
    argv = (
        ["build", str(spec), "-o", str(out / "robot.xml")] if robot else ["validate", "--compile", str(spec)]
    )
    tables = (REGISTERED_ROBOTS, REGISTERED_BASES, REGISTERED_GRIPPERS)
    snapshots = [dict(table) for table in tables]
    motors = MOTORS.state()  # a motor spec registers its name too
    try:
        code = main(argv)  # any exception but AssemblerError escapes here and fails the test
    finally:
        for table, snapshot in zip(tables, snapshots, strict=True):
            table.clear()
            table.update(snapshot)
        MOTORS.restore(motors)
    err = capsys.readouterr().err
    assert code in (0, 1)
    if currently_in_test_context():
        event(f"exit code {code} ({argv[0]})")  # shown by --hypothesis-show-statistics
    written = sorted(p.name for p in out.iterdir())
    if code == 1:
        assert err.strip(), "a failure must say why"
        assert "Traceback" not in err
        assert written == [], "a failed build writes nothing"
    elif robot:
        # one whole file, no temporary beside it; and the meshes it names that the build converted
        # (URDF COLLADA), copied beside it: a written model never points into the cache
        assert written in (["robot.xml"], ["robot.xml", "robot.xml-assets"]), written
        assert mujoco.MjModel.from_xml_path(str(out / "robot.xml")).nbody > 1
    return code


@FUZZ
@given(content=mutated_spec)
def test_mutated_shipped_specs_build_or_fail_cleanly(
    isolated: Path, capsys: pytest.CaptureFixture[str], content: bytes
) -> None:
    _run_case(isolated, content, capsys)


@FUZZ
@given(content=schema_spec())
def test_specs_drawn_from_the_schema_build_or_fail_cleanly(
    isolated: Path, capsys: pytest.CaptureFixture[str], content: bytes
) -> None:
    _run_case(isolated, content, capsys)


@FUZZ
@given(files=extends_folder())
def test_chains_and_cycles_of_extends_and_odd_paths_build_or_fail_cleanly(
    isolated: Path, capsys: pytest.CaptureFixture[str], files: dict[str, bytes]
) -> None:
    others = {name: text for name, text in files.items() if name != "spec.yaml"}
    _run_case(isolated, files["spec.yaml"], capsys, others)


def test_the_unmutated_shipped_specs_build(isolated: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The fuzzer's starting points are valid: mutations start from working specs."""
    assert len(SHIPPED) >= 10
    assert [_run_case(isolated, text.encode(), capsys) for text in SHIPPED] == [0] * len(SHIPPED)
