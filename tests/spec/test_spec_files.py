"""The loader: YAML with positions, inheritance, and one clear line per problem."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.errors import SpecError
from assembler.files.paths import display_path
from assembler.spec.spec_files import load_paths, load_string

Write = Callable[[str, str], Path]

# Each row: spec text, the exact message expected (after "<file>:").
INVALID_SPECS = [
    pytest.param(
        "name: A\nname: B\nmjcf: a.xml\n",
        "2:1: name: duplicate key 'name' (first at line 1); keep one",
        id="duplicate-key",
    ),
    pytest.param(
        "name: A\nmjcf: [a.xml\n",
        "3:1: YAML syntax error: expected ',' or ']', but got '<stream end>'",
        id="yaml-syntax",
    ),
    pytest.param("mjcf: a.xml\n", "1:1: missing required field 'name'; add it", id="missing-name"),
    pytest.param(
        "name: A\n", "1:1: give exactly one of mjcf and urdf (the model file), got neither", id="missing-mjcf"
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\njoint_defaults:\n  dampng: 0.1\n",
        "4:3: joint_defaults.dampng: unknown key 'dampng'. Did you mean 'damping'? Valid keys here: armature, damping, frictionloss",
        id="unknown-nested-key",
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\ninit_qpos: [0, zero]\n",
        "3:16: init_qpos[1]: Input should be a valid number, unable to parse string as a number",
        id="wrong-type-in-list",
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\ninit_qpos: [0, .nan]\n",
        "3:16: init_qpos[1]: Input should be a finite number",
        id="nan",
    ),
    pytest.param(
        "name: 7up\nmjcf: a.xml\n",
        "1:7: name: String should match pattern '^[A-Za-z][A-Za-z0-9_]*$'",
        id="bad-name",
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\njoint_defaults:\n  armature: {inverse: 5}\n",
        "4:13: joint_defaults.armature: expected a non-negative number, a list of them (one per joint), "
        "a mapping 'inverse_index: <scale>' or null, got {'inverse': 5}",
        id="bad-rule",
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\nbase_xpos_offset:\n  table: [\"__import__('os')\", 0, 0]\n",
        '4:11: base_xpos_offset.table[0]: unexpected character "\'" in expression "__import__(\'os\')"',
        id="offset-expression-is-not-python",
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\ntop_offset: [0, 0]\n",
        "3:13: top_offset: expected 3 values, got 2",
        id="vector-too-short",
    ),
    pytest.param(
        "name: A\nmjcf: a.xml\njoints:\n  - match: j1\n",
        "4:5: joints[0]: Value error, override for 'j1' sets nothing; give one of frictionloss, damping, armature, stiffness",
        id="override-without-values",
    ),
    pytest.param("- name: A\n", "1:1: a spec must be a YAML mapping (key: value lines)", id="list-document"),
    pytest.param("", "a spec is a YAML mapping", id="empty-file"),
    pytest.param(
        "name: A\nmjcf: a.xml\nbase_xpos_offset:\n  table: [os.system, 0, 0]\n",
        "4:11: base_xpos_offset.table[0]: unexpected character '.' in expression 'os.system'",
        id="offset-expression-with-attribute-access",
    ),
    pytest.param(
        "name: !!python/object/apply:os.system [ls]\nmjcf: a\n",
        "1:7: name: YAML tag 'tag:yaml.org,2002:python/object/apply:os.system' is not allowed; specs are plain data",
        id="python-tag",
    ),
]


@pytest.mark.parametrize(("text", "expected"), INVALID_SPECS)
def test_invalid_spec_gives_one_exact_line(write: Write, text: str, expected: str) -> None:
    path = write("specs/bad.yaml", text)
    with pytest.raises(SpecError) as caught:
        load_paths([path])
    lines = str(caught.value).splitlines()
    assert len(lines) == 1
    assert lines[0].startswith(display_path(path) + ":")
    assert lines[0].endswith(expected)


def test_every_problem_of_every_file_is_reported(write: Write) -> None:
    write("specs/a.yaml", "name: A\n")
    write("specs/b.yaml", "name: B\nmjcf: b.xml\nbogus: 1\n")
    with pytest.raises(SpecError) as caught:
        load_paths([write("specs/c.yaml", "mjcf: c.xml\n").parent])
    messages = [p.message for p in caught.value.problems]
    assert len(messages) == 3
    assert any("unknown key 'bogus'" in m for m in messages)


def test_windows_line_endings_and_bom_just_work(write: Write) -> None:
    path = write("specs/a.yaml", "")
    path.write_bytes(b"\xef\xbb\xbfname: A\r\nmjcf: a.xml\r\n")
    (loaded,) = load_paths([path])
    assert loaded.spec.name == "A"


def test_non_utf8_text_is_refused_with_its_position(write: Write) -> None:
    path = write("specs/a.yaml", "")
    path.write_bytes(b"name: A\nmjcf: \xff.xml\n")
    with pytest.raises(SpecError, match=r"a.yaml: the file is not UTF-8 text \(byte 14\)"):
        load_paths([path])


def test_extends_a_file_inherits_and_overrides_fields(
    write: Write, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    monkeypatch.setenv("ASSEMBLER_ALLOW_PATHS", str(tmp_path))  # the parent sits in a sibling folder
    write(
        "specs/parent.yaml",
        "name: Parent\nmjcf: models/p.xml\ninit_qpos: [1, 2]\njoint_defaults:\n  damping: 0.3\n",
    )
    child = write(
        "specs/variants/child.yaml",
        "name: Child\nextends: ../parent.yaml\njoint_defaults:\n  frictionloss: 0.0\n",
    )
    (loaded,) = load_paths([child])
    spec = loaded.spec
    assert spec.name == "Child"
    assert spec.init_qpos == [1.0, 2.0]
    assert spec.joint_defaults.damping == 0.3  # merged key by key
    assert spec.joint_defaults.frictionloss == 0.0
    # the parent's relative mjcf path stays relative to the parent's own folder
    assert spec.mjcf == str(child.parent.parent / "models" / "p.xml")


def test_extends_a_registered_robot_by_name(two_link: Path, write: Write) -> None:
    assembler.register_specs(two_link)
    loaded = load_string(
        "name: TwoLinkSoft\nextends: TwoLink\njoint_defaults: {damping: 0.01}\n",
        assembler.registry.catalog.PARENTS,
    )
    assert loaded.spec.init_qpos == [0.5, -0.5]
    assert loaded.spec.mjcf == str(two_link.parent / "twolink.xml")


def test_errors_in_inherited_fields_point_at_the_file_that_wrote_them(write: Write) -> None:
    write("specs/parent.yaml", "name: Parent\nmjcf: p.xml\ninit_qpos: [1, x]\n")
    child = write("specs/child.yaml", "name: Child\nextends: parent.yaml\n")
    with pytest.raises(SpecError) as caught:
        load_paths([child])
    assert str(caught.value).endswith(
        "parent.yaml:3:16: init_qpos[1]: Input should be a valid number, unable to parse string as a number"
    )


def test_inheritance_cycle_is_named(write: Write) -> None:
    write("specs/a.yaml", "name: A\nextends: B\nmjcf: a.xml\n")
    write("specs/b.yaml", "name: B\nextends: A\nmjcf: b.xml\n")
    with pytest.raises(SpecError) as caught:
        load_paths([write("specs/c.yaml", "name: C\nmjcf: c.xml\n").parent])
    (line,) = str(caught.value).splitlines()  # one cycle, one line, whichever file meets it first
    assert line.endswith(".yaml:2:10: extends: inheritance cycle: A -> B -> A; break it")


def test_unknown_parent_suggests_the_closest_name(two_link: Path) -> None:
    assembler.register_specs(two_link)
    with pytest.raises(SpecError, match=r"extends: unknown robot spec 'TwoLnk'. Did you mean 'TwoLink'\?$"):
        load_string("name: X\nextends: TwoLnk\n", assembler.registry.catalog.PARENTS)


def test_missing_parent_file_is_reported(write: Write) -> None:
    child = write("specs/child.yaml", "name: Child\nextends: nowhere.yaml\n")
    with pytest.raises(
        SpecError, match=r"child.yaml:2:10: extends: parent spec file not found: .*nowhere.yaml"
    ):
        load_paths([child])


def test_missing_path_is_one_line() -> None:
    with pytest.raises(SpecError, match=r"^no such file or folder: does/not/exist$"):
        load_paths(["does/not/exist"])
