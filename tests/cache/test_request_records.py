"""Request records: ``assembler.load_model`` and ``assembler build`` answer a request made before
without reading a spec, and never with a wrong model: a changed spec file, parent file, override,
idn, base or gripper choice, spec folder, package location or code is a miss, answered right."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

import assembler
from assembler.answers.records import _record_of, keyed
from assembler.cache import requests as request_records
from assembler.cache.requests import default_request_store, request_key
from assembler.cli import main
from assembler.compiler.service import wait_for_writes
from tests.conftest import use_private_cache

ARM = """\
<mujoco model="arm">
  <compiler angle="radian"/>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="cylinder" size="0.05 0.05" mass="2"/>
      <body name="link1" pos="0 0 0.1">
        <joint name="joint1" axis="0 0 1" range="-3 3"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.2 0 0" size="0.02" mass="1"/>
        <body name="right_hand" pos="0.2 0 0"/>
      </body>
    </body>
  </worldbody>
  <actuator><position name="act1" joint="joint1" kp="50" ctrlrange="-3 3"/></actuator>
</mujoco>
"""

ARM_SPEC = "name: Arm\nmjcf: arm.xml\njoint_defaults: {{damping: {damping}}}\n"


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    folder = use_private_cache(tmp_path / "model-cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    yield folder
    wait_for_writes()


def edit(path: Path, text: str, seconds_ago: float = 60) -> None:
    """Write ``path`` as if some time ago (files changed in the last seconds are not recorded)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    then = time.time() - seconds_ago
    os.utime(path, (then, then))


@pytest.fixture
def arms(tmp_path: Path) -> Path:
    """A spec folder: Arm (damping 0.3) in ``parts/``, and ArmChild, which extends it by file."""
    folder = tmp_path / "arms"
    edit(folder / "parts" / "arm.xml", ARM, 3600)
    edit(folder / "parts" / "arm.yaml", ARM_SPEC.format(damping=0.3), 3600)
    edit(folder / "arm_child.yaml", "name: ArmChild\nextends: parts/arm.yaml\n", 3600)
    for place in (folder, folder / "parts"):
        os.utime(place, (time.time() - 3600,) * 2)
    return folder


def damping(name: str, folder: Path, **kwargs: object) -> float:
    """The robot's first joint damping, through ``load_model`` (its entry written before returning)."""
    model = assembler.load_model(name, specs=[folder], **kwargs)  # type: ignore[arg-type]
    wait_for_writes()
    return float(model.dof_damping[0])


def records() -> int:
    folder = default_request_store().directory
    return len(list(folder.glob("*.json"))) if folder.is_dir() else 0


def answered(name: str, folder: Path, **kwargs: object) -> bool:
    """Whether ``load_model`` would answer from a record now (nothing is loaded)."""
    request = {
        "kind": "load_model",
        "robot": name,
        "idn": kwargs.get("idn", 0),
        "base": kwargs.get("base", "default"),
        "grippers": None,
        "overrides": kwargs.get("overrides"),
        "specs": [str(folder.resolve())],
    }
    return _record_of(keyed(request)) is not None


def test_a_repeated_request_is_answered_from_its_record(arms: Path) -> None:
    assert damping("Arm", arms) == pytest.approx(0.3)
    assert records() == 1 and answered("Arm", arms)
    assert damping("Arm", arms) == pytest.approx(0.3)


def test_an_edited_spec_file_is_a_miss(arms: Path) -> None:
    assert damping("Arm", arms) == pytest.approx(0.3)
    edit(arms / "parts" / "arm.yaml", ARM_SPEC.format(damping=0.7), 30)
    assert not answered("Arm", arms)
    assert damping("Arm", arms) == pytest.approx(0.7)


def test_an_edited_parent_file_is_a_miss_for_the_child(arms: Path) -> None:
    assert damping("ArmChild", arms) == pytest.approx(0.3)
    assert answered("ArmChild", arms)
    edit(arms / "parts" / "arm.yaml", ARM_SPEC.format(damping=0.9), 30)
    assert not answered("ArmChild", arms)
    assert damping("ArmChild", arms) == pytest.approx(0.9)


def test_a_touched_but_unchanged_spec_still_answers(arms: Path) -> None:
    damping("Arm", arms)
    os.utime(arms / "parts" / "arm.yaml", (time.time() - 30,) * 2)
    assert answered("Arm", arms)


def test_a_spec_file_added_to_a_spec_folder_is_a_miss(arms: Path) -> None:
    damping("Arm", arms)
    edit(
        arms / "parts" / "other.yaml", "name: Arm\nmjcf: arm.xml\n", 30
    )  # the same name: the slow path refuses
    assert not answered("Arm", arms)
    with pytest.raises(assembler.RegistryError, match="already|also defined"):
        damping("Arm", arms)


@pytest.mark.parametrize(
    ("changed", "expected"),
    [
        ({"overrides": {"joint_defaults.damping": 0.5}}, 0.5),
        ({"overrides": ["joint_defaults.damping=0.25"]}, 0.25),
        ({"idn": 1}, 0.3),
    ],
)
def test_another_override_or_idn_is_another_request(
    arms: Path, changed: dict[str, object], expected: float
) -> None:
    damping("Arm", arms)
    assert not answered("Arm", arms, **changed)
    model = assembler.load_model("Arm", specs=[arms], **changed)  # type: ignore[arg-type]
    assert model.dof_damping[0] == pytest.approx(expected)
    assert model.joint(0).name == f"robot{changed.get('idn', 0)}_joint1"


def test_another_base_or_gripper_choice_is_another_request() -> None:
    with_gripper = assembler.load_model("Sparrow7")
    wait_for_writes()
    bare = assembler.load_model("Sparrow7", base=None, grippers={"right": None})
    assert bare.nbody < with_gripper.nbody
    assert assembler.load_model("Sparrow7").nbody == with_gripper.nbody


def test_a_code_change_is_a_miss(arms: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    damping("Arm", arms)
    monkeypatch.setattr(request_records, "code_fingerprint", lambda: "another version of the assembler")
    assert not answered("Arm", arms)


def test_a_broken_record_is_removed_and_answered_the_slow_way(arms: Path) -> None:
    damping("Arm", arms)
    (record,) = default_request_store().directory.glob("*.json")
    record.write_text('{"format": 1, "model_key": ')
    assert damping("Arm", arms) == pytest.approx(0.3)
    assert records() == 1 and record.read_text().endswith("}")


def test_a_spec_registered_as_text_is_never_recorded(arms: Path) -> None:
    assembler.register_spec_string("name: TextArm\nmjcf: " + str(arms / "parts" / "arm.xml") + "\n")
    assembler.load_model("TextArm", specs=[arms])
    assert records() == 0


def test_requests_in_environments_with_another_package_location_do_not_share_records(tmp_path: Path) -> None:
    edit(tmp_path / "fake.yaml", "name: FakeBot\nmjcf: package://fakebot/robot.xml\n", 3600)
    script = (
        "import sys, assembler, assembler.compiler.service; m = assembler.load_model(sys.argv[1]); "
        "assembler.compiler.service.wait_for_writes(); "
        "print(m.geom('robot0_base_col').size[0], 'assembler.registry.catalog' in sys.modules)"
    )
    seen = []
    for install, radius in (("a", "0.3"), ("b", "0.9"), ("a", "0.3")):
        package = tmp_path / install / "fakebot"
        edit(package / "__init__.py", "", 3600)
        edit(package / "robot.xml", ARM.replace('size="0.05 0.05"', f'size="{radius} 0.05"'), 3600)
        environment = {
            **os.environ,
            "PYTHONPATH": str(tmp_path / install),
            "ASSEMBLER_ALLOW_PATHS": str(tmp_path),
        }
        done = subprocess.run(
            [sys.executable, "-c", script, str(tmp_path / "fake.yaml")],
            env=environment,
            capture_output=True,
            text=True,
            check=True,
        )
        size, catalog = done.stdout.split()
        seen.append((float(size), catalog == "True"))
    assert seen == [(0.3, True), (0.9, True), (0.3, False)]  # the third from its record: no spec read


def test_a_repeated_build_reads_no_spec_and_writes_the_same_file(tmp_path: Path) -> None:
    script = (
        "import sys; from assembler.cli import main; code = main(sys.argv[1:]); "
        "print('pydantic' in sys.modules, code)"
    )
    command = [sys.executable, "-c", script, "build", "Sparrow7", "--set", "joint_defaults.damping=0.2"]
    runs = []
    for index in range(2):
        output = tmp_path / f"sparrow{index}.xml"
        done = subprocess.run([*command, "-o", str(output)], capture_output=True, text=True, check=True)
        runs.append((done.stdout.split(), done.stderr.replace(output.name, "OUT")))
    assert [stdout for stdout, _ in runs] == [["True", "0"], ["False", "0"]]
    assert runs[0][1] == runs[1][1] == "wrote OUT\n"
    assert (tmp_path / "sparrow0.xml").read_bytes() == (tmp_path / "sparrow1.xml").read_bytes()


def test_a_repeated_build_prints_the_same_warnings(capsys: pytest.CaptureFixture[str]) -> None:
    flags = [
        "build",
        "Sparrow7",
        "--set",
        'joints=[{match: "*", damping: 1.0}]',
        "--set",
        "joint_defaults.damping=0.2",
    ]
    assert main([*flags, "-o", "a.xml"]) == 0
    first = capsys.readouterr().err
    wait_for_writes()
    assert main([*flags, "-o", "a.xml"]) == 0
    assert capsys.readouterr().err == first and "joint_defaults.damping changes nothing" in first


@pytest.mark.parametrize("flag", [["--allow-path", "."], ["--specs", "."], ["--no-base"], ["--idn", "2"]])
def test_build_flags_that_decide_the_answer_are_in_the_request(flag: list[str]) -> None:
    from assembler.answers.build_request import build_request
    from assembler.cli.arguments import parse
    from assembler.cli.cached_build import build_flags

    plain = build_request(build_flags(parse(["build", "Sparrow7"])))
    other = build_request(build_flags(parse(["build", "Sparrow7", *flag])))
    assert plain is not None and other is not None and request_key(plain) != request_key(other)
