"""Faults while writing: the user's existing files survive, no half-written or temporary file is
left behind, and a bundle never writes outside its folder."""

from __future__ import annotations

import os
import resource
import signal
import subprocess
import sys
from pathlib import Path

import mujoco
import pytest

import assembler
from assembler.cli import main
from assembler.files import writing
from tests.conftest import TETRAHEDRON_OBJ, TWO_LINK_MJCF

CLI = "import sys; from assembler.cli import run; sys.exit(run())"
"""The ``assembler`` command, run by this Python in a new process."""

OLD = "<mujoco model='the user's previous output'/>\n"


def _spec_folder(tmp_path: Path) -> Path:
    folder = tmp_path / "specs"
    folder.mkdir()
    (folder / "twolink.xml").write_text(TWO_LINK_MJCF)
    (folder / "arm.yaml").write_text("name: Arm\nmjcf: twolink.xml\n")
    (folder / "broken.xml").write_text(TWO_LINK_MJCF.replace('mass="0.5"', 'mass="-0.5"'))
    (folder / "broken.yaml").write_text("name: Broken\nmjcf: broken.xml\n")
    return folder


def _previous_output(tmp_path: Path) -> Path:
    out = tmp_path / "out" / "robot.xml"
    out.parent.mkdir()
    out.write_text(OLD)
    return out


def test_a_build_that_fails_leaves_the_existing_output_intact(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    spec, out = _spec_folder(tmp_path) / "broken.yaml", _previous_output(tmp_path)
    assert main(["build", str(spec), "-o", str(out)]) == 1
    assert (
        "broken.xml:23: MuJoCo refuses it: mass, inertia or density are negative" in capsys.readouterr().err
    )
    assert out.read_text() == OLD
    assert os.listdir(out.parent) == ["robot.xml"]


def _limit_file_size() -> None:
    # A real write that fails half way: the kernel refuses bytes past 4 KiB with EFBIG.
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))


def test_a_write_that_fails_half_way_keeps_the_old_file_and_leaves_no_temporary(tmp_path: Path) -> None:
    out = _previous_output(tmp_path)
    environment = {**os.environ, "ASSEMBLER_NO_CACHE": "1", "PYTHONDONTWRITEBYTECODE": "1"}
    done = subprocess.run(
        [sys.executable, "-c", CLI, "build", "Sparrow7", "-o", str(out)],
        capture_output=True,
        text=True,
        env=environment,
        preexec_fn=_limit_file_size,
        timeout=300,
    )
    assert (done.returncode, done.stderr) == (1, f"cannot write {out}: File too large\n")
    assert out.read_text() == OLD
    assert os.listdir(out.parent) == ["robot.xml"]


def test_a_failed_rename_keeps_the_old_file_and_leaves_no_temporary(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    spec, out = _spec_folder(tmp_path) / "arm.yaml", _previous_output(tmp_path)

    def refuse(source: object, target: object) -> None:
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(writing.os, "replace", refuse)
    assert main(["build", str(spec), "-o", str(out)]) == 1
    assert capsys.readouterr().err == f"cannot write {out}: Permission denied\n"
    assert out.read_text() == OLD
    assert os.listdir(out.parent) == ["robot.xml"]


def test_ctrl_c_while_writing_keeps_the_old_file_and_leaves_no_temporary(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    out = _previous_output(tmp_path)

    def interrupt(descriptor: int) -> None:
        raise KeyboardInterrupt

    monkeypatch.setattr(writing.os, "fsync", interrupt)
    with pytest.raises(KeyboardInterrupt):
        writing.write_atomically(out, "<mujoco/>")
    assert out.read_text() == OLD
    assert os.listdir(out.parent) == ["robot.xml"]


def test_an_output_below_a_file_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "afile").write_text("")
    assert main(["build", "Sparrow7", "-o", str(tmp_path / "afile" / "x.xml")]) == 1
    assert capsys.readouterr().err == f"cannot write {tmp_path}/afile/x.xml: a folder on its path is a file\n"


def test_a_folder_named_like_a_spec_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "robot.yaml").mkdir()
    assert main(["build", str(tmp_path / "robot.yaml")]) == 1
    assert (
        capsys.readouterr().err == f"{tmp_path}/robot.yaml: no spec in it; give a spec file or a robot name\n"
    )


@pytest.mark.skipif(os.geteuid() == 0, reason="root reads files whatever their permissions")
def test_unreadable_spec_and_mjcf_are_one_line_each(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    folder = _spec_folder(tmp_path)
    (folder / "arm.yaml").chmod(0)
    assert main(["build", str(folder / "arm.yaml")]) == 1
    assert capsys.readouterr().err == f"{folder}/arm.yaml: cannot read the file: Permission denied\n"
    (folder / "arm.yaml").chmod(0o644)
    (folder / "twolink.xml").chmod(0)
    assert main(["build", str(folder / "arm.yaml")]) == 1
    assert capsys.readouterr().err == (
        f"{folder}/arm.yaml:2:7: mjcf: {folder}/twolink.xml: cannot read the file: Permission denied\n"
    )


STRANGE_NAMES_MJCF = """\
<mujoco model="strange">
  <asset>
    <mesh name="a" file="..tetra.obj"/>
    <mesh name="b" file="we ird$(name).obj"/>
    <mesh name="c" file=".hidden.obj"/>
  </asset>
  <worldbody>
    <body name="base">
      <joint name="spin" axis="0 0 1"/>
      <geom type="mesh" mesh="a"/><geom type="mesh" mesh="b"/><geom type="mesh" mesh="c"/>
    </body>
  </worldbody>
</mujoco>
"""


def test_a_bundle_writes_only_plain_names_inside_its_folder(tmp_path: Path) -> None:
    robot = tmp_path / "robot"
    robot.mkdir()
    for name in ("..tetra.obj", "we ird$(name).obj", ".hidden.obj"):
        (robot / name).write_text(TETRAHEDRON_OBJ)
    (robot / "strange.xml").write_text(STRANGE_NAMES_MJCF)
    (robot / "strange.yaml").write_text("name: Strange\nmjcf: strange.xml\n")
    assert main(["build", str(robot / "strange.yaml"), "--bundle", str(tmp_path / "bundle")]) == 0
    written = sorted(str(p.relative_to(tmp_path)) for p in tmp_path.rglob("*") if p.is_file())
    assert written == [
        "bundle/.assembler-bundle.json",  # the bundle's record of its own files
        "bundle/Strange.xml",
        "bundle/assets/hidden.obj",
        "bundle/assets/tetra.obj",
        "bundle/assets/we_ird__name_.obj",
        "robot/..tetra.obj",
        "robot/.hidden.obj",
        "robot/strange.xml",
        "robot/strange.yaml",
        "robot/we ird$(name).obj",
    ]
    assert mujoco.MjModel.from_xml_path(str(tmp_path / "bundle" / "Strange.xml")).nmesh == 3


def test_a_bundle_refuses_an_assets_link_leading_out(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    (tmp_path / "bundle").mkdir()
    (tmp_path / "bundle" / "assets").symlink_to(elsewhere)
    assert main(["build", "Sparrow7", "--bundle", str(tmp_path / "bundle")]) == 1
    assert capsys.readouterr().err == f"{tmp_path}/bundle/assets leads out of {tmp_path}/bundle; remove it\n"
    assert list(elsewhere.iterdir()) == []
    assert assembler.REGISTERED_ROBOTS["Sparrow7"] is not None


def test_a_bundle_that_fails_leaves_no_folder_and_no_file_behind(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    def disk_full(source: object, target: object) -> None:
        raise OSError(28, "No space left on device")

    robot = tmp_path / "robot"
    robot.mkdir()
    (robot / "tet.obj").write_text(TETRAHEDRON_OBJ)
    mjcf = TWO_LINK_MJCF.replace("<worldbody>", '<asset><mesh name="tet" file="tet.obj"/></asset><worldbody>')
    mjcf = mjcf.replace(
        '<geom name="base_col"', '<geom type="mesh" mesh="tet" group="1"/><geom name="base_col"'
    )
    (robot / "arm.xml").write_text(mjcf)
    (robot / "arm.yaml").write_text("name: MeshArm\nmjcf: arm.xml\n")
    monkeypatch.setattr(writing.shutil, "copyfileobj", disk_full)
    bundle = tmp_path / "out" / "deep" / "bundle"
    assert main(["build", str(robot / "arm.yaml"), "--bundle", str(bundle)]) == 1
    assert capsys.readouterr().err.endswith(": No space left on device\n")
    assert not (tmp_path / "out").exists()  # neither out/ nor deep/ nor bundle/ nor assets/


def test_cache_clear_says_what_it_could_not_remove(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.delenv("ASSEMBLER_NO_CACHE", raising=False)
    assert main(["build", "Sparrow7", "-o", str(tmp_path / "a.xml")]) == 0
    assembler.compiler.service.wait_for_writes()
    real_unlink = Path.unlink

    def read_only(path: Path, missing_ok: bool = False) -> None:
        if path.parent == tmp_path / "cache":
            raise PermissionError(13, "Permission denied")
        real_unlink(path, missing_ok=missing_ok)

    monkeypatch.setattr(Path, "unlink", read_only)
    capsys.readouterr()
    assert main(["cache", "clear"]) == 1
    (line,) = capsys.readouterr().err.splitlines()
    assert line.startswith(
        f"could not remove 3 file(s) from {tmp_path / 'cache'}; first: "
    )  # manifest, model, XML
    assert line.endswith(": Permission denied")


def test_cache_info_says_when_the_cache_cannot_be_used(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "a-file").write_text("")
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "a-file" / "cache"))
    monkeypatch.delenv("ASSEMBLER_NO_CACHE", raising=False)
    assert main(["cache", "info"]) == 0
    (status,) = [line for line in capsys.readouterr().out.splitlines() if line.startswith("status ")]
    assert status.split(None, 1)[1] == f"unusable: {tmp_path / 'a-file'} is a file, not a folder"
