"""Files a spec names stay where they belong: its own folder, the shipped folders, packages, or
folders the user allowed; MJCF is refused before parsing when it declares a DTD (entities)."""

from __future__ import annotations

import importlib
import os
from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from assembler.errors import MjcfError, SpecError
from assembler.files.paths import ALLOW_VARIABLE, allow_paths
from tests.conftest import TETRAHEDRON_OBJ, TWO_LINK_MJCF

Write = Callable[[str, str], Path]

OUTSIDE = "is outside the folders a spec may read (its own folder, the shipped specs and assets, installed packages); pass --allow-path DIR (or set ASSEMBLER_ALLOW_PATHS) to allow it"

MESH_MJCF = """\
<mujoco model="meshy">
  <compiler meshdir="{meshdir}"/>
  <asset><mesh name="tetra" file="{file}"/></asset>
  <worldbody>
    <body name="base"><joint name="spin" axis="0 0 1"/><geom type="mesh" mesh="tetra"/></body>
  </worldbody>
</mujoco>
"""


@pytest.fixture(autouse=True)
def no_allowed_paths(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(ALLOW_VARIABLE, raising=False)


def _build(argv: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, list[str]]:
    code = main(argv)
    return code, capsys.readouterr().err.splitlines()


def test_mjcf_path_escaping_with_dotdot_is_refused_and_allow_path_admits_it(
    write: Write, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write("outside/twolink.xml", TWO_LINK_MJCF)
    spec = write("specs/arm.yaml", "name: Arm\nmjcf: ../outside/twolink.xml\n")
    code, err = _build(["build", str(spec), "-o", str(tmp_path / "arm.xml")], capsys)
    assert code == 1
    assert err == [f"{spec}:2:7: mjcf: {tmp_path}/outside/twolink.xml {OUTSIDE}"]
    assert not (tmp_path / "arm.xml").exists()
    allowed = ["--allow-path", str(tmp_path / "outside"), "build", str(spec), "-o", str(tmp_path / "arm.xml")]
    assert _build(allowed, capsys) == (0, [f"wrote {tmp_path}/arm.xml"])
    assert os.environ.get(ALLOW_VARIABLE) is None  # the flag lasts one run


def test_absolute_mjcf_path_outside_is_refused(write: Write) -> None:
    target = write("outside/twolink.xml", TWO_LINK_MJCF)
    spec = write("specs/arm.yaml", f"name: Arm\nmjcf: {target}\n")
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == f"{spec}:2:7: mjcf: {target} {OUTSIDE}"


def test_a_missing_file_outside_is_refused_as_an_existing_one_is(write: Write, tmp_path: Path) -> None:
    # No existence oracle: a stranger's spec must not learn which files exist outside by the message.
    spec = write("specs/arm.yaml", "name: Arm\nmjcf: ../outside/twolink.xml\n")
    messages = []
    for exists in (False, True):
        if exists:
            write("outside/twolink.xml", TWO_LINK_MJCF)
        with pytest.raises(SpecError) as caught:
            assembler.register_specs(spec)
        messages.append(str(caught.value))
    assert messages == [f"{spec}:2:7: mjcf: {tmp_path}/outside/twolink.xml {OUTSIDE}"] * 2


def test_a_file_linked_out_after_loading_is_refused_when_read(write: Write, tmp_path: Path) -> None:
    inside = write("specs/twolink.xml", TWO_LINK_MJCF)
    spec = write("specs/arm.yaml", "name: Arm\nmjcf: twolink.xml\n")
    (cls,) = assembler.register_specs(spec)
    target = write("outside/twolink.xml", TWO_LINK_MJCF)
    inside.unlink()
    inside.symlink_to(target)  # re-pointed between loading and reading
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == f"{spec}:2:7: mjcf: {inside} (a link to {target}) {OUTSIDE}"


def test_a_symbolic_link_leading_out_is_refused_and_named(write: Write, tmp_path: Path) -> None:
    target = write("outside/twolink.xml", TWO_LINK_MJCF)
    (tmp_path / "specs").mkdir()
    (tmp_path / "specs" / "link.xml").symlink_to(target)
    spec = write("specs/arm.yaml", "name: Arm\nmjcf: link.xml\n")
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == f"{spec}:2:7: mjcf: {tmp_path}/specs/link.xml (a link to {target}) {OUTSIDE}"


def test_a_link_inside_the_spec_folder_is_fine(write: Write, tmp_path: Path) -> None:
    target = write("specs/models/twolink.xml", TWO_LINK_MJCF)
    (tmp_path / "specs" / "link.xml").symlink_to(target)
    (cls,) = assembler.register_specs(write("specs/arm.yaml", "name: Arm\nmjcf: link.xml\n"))
    assert cls(idn=0).get_model().njnt == 2


def test_parent_spec_outside_is_refused(write: Write) -> None:
    write("outside/parent.yaml", "name: Parent\nmjcf: twolink.xml\n")
    spec = write("specs/child.yaml", "name: Child\nextends: ../outside/parent.yaml\n")
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == f"{spec}:2:10: extends: {spec.parent.parent}/outside/parent.yaml {OUTSIDE}"


@pytest.mark.parametrize(
    ("meshdir", "file"),
    [
        pytest.param("../../outside", "tetra.obj", id="meshdir-escapes"),
        pytest.param("meshes", "../../../outside/tetra.obj", id="file-escapes"),
        pytest.param("meshes", "{tmp}/outside/tetra.obj", id="absolute-file"),
    ],
)
def test_mesh_files_outside_are_refused_before_mujoco_reads_them(
    write: Write, tmp_path: Path, meshdir: str, file: str
) -> None:
    write("outside/tetra.obj", TETRAHEDRON_OBJ)
    write("specs/robot/meshy.xml", MESH_MJCF.format(meshdir=meshdir, file=file.format(tmp=tmp_path)))
    (cls,) = assembler.register_specs(write("specs/meshy.yaml", "name: Meshy\nmjcf: robot/meshy.xml\n"))
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == (
        f"{tmp_path}/specs/meshy.yaml:2:7: mjcf: {tmp_path}/specs/robot/meshy.xml: asset file "
        f"{tmp_path}/outside/tetra.obj {OUTSIDE}"
    )


def test_meshes_anywhere_below_the_spec_folder_are_fine(write: Write) -> None:
    write("specs/meshes/tetra.obj", TETRAHEDRON_OBJ)  # beside the MJCF's folder, not below it
    write("specs/robot/meshy.xml", MESH_MJCF.format(meshdir="../meshes", file="tetra.obj"))
    (cls,) = assembler.register_specs(write("specs/meshy.yaml", "name: Meshy\nmjcf: robot/meshy.xml\n"))
    assert cls(idn=0).get_model().nmesh == 1


def test_allow_paths_in_python_admits_a_folder(write: Write, tmp_path: Path) -> None:
    write("outside/twolink.xml", TWO_LINK_MJCF)
    spec = write("specs/arm.yaml", "name: Arm\nmjcf: ../outside/twolink.xml\n")
    allow_paths(tmp_path / "outside")
    (cls,) = assembler.register_specs(spec)
    assert cls(idn=0).get_model().njnt == 2


@pytest.mark.parametrize(
    ("reference", "message"),
    [
        pytest.param(  # enough ".." to reach / from any site-packages (".." of / is /)
            "package://robosuite/" + "../" * 30 + "etc/hostname",
            "package://robosuite/" + "../" * 30 + "etc/hostname: /etc/hostname " + OUTSIDE,
            id="dotdot-out-of-the-package",
        ),
        pytest.param(  # the same line for a file that does not exist: no existence oracle
            "package://robosuite/" + "../" * 30 + "etc/no-such-file",
            "package://robosuite/" + "../" * 30 + "etc/no-such-file: /etc/no-such-file " + OUTSIDE,
            id="dotdot-out-of-the-package-to-a-missing-file",
        ),
        pytest.param(
            "package://os.path/x.xml",
            "package://os.path/x.xml: expected package://<top-level package>/<path in it>",
            id="dotted-package-name",
        ),
    ],
)
def test_package_paths_stay_in_their_package(write: Write, reference: str, message: str) -> None:
    pytest.importorskip("robosuite")
    spec = write("specs/arm.yaml", f"name: Arm\nmjcf: {reference}\n")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == f"{spec}:2:7: mjcf: {message}"


def test_a_package_installed_inside_a_spec_repository_is_confined_to_the_package(
    write: Write, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # A virtual environment inside a checkout (CI's .ci-venv): the repository around the package's
    # folder is not what the package's files may reach, and the refusal must not claim it is.
    write("checkout/pyproject.toml", '[project]\nname = "lab"\n\n[tool.robot-assembler]\n')
    write("checkout/specs/.keep", "")
    write("checkout/venv/site/vendored_arm_pkg/__init__.py", "")
    monkeypatch.syspath_prepend(str(tmp_path / "checkout" / "venv" / "site"))
    reference = "package://vendored_arm_pkg/" + "../" * 30 + "etc/hostname"
    spec = write("specs/arm.yaml", f"name: Arm\nmjcf: {reference}\n")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == f"{spec}:2:7: mjcf: {reference}: /etc/hostname {OUTSIDE}"


def test_a_spec_file_linked_into_a_folder_from_outside_is_refused(write: Write, tmp_path: Path) -> None:
    secret = write("home/.env", "SECRET_TOKEN: abc123\n")
    write("specs/arm.yaml", "name: Arm\nmjcf: twolink.xml\n")
    write("specs/twolink.xml", TWO_LINK_MJCF)
    (tmp_path / "specs" / "env.yaml").symlink_to(secret)
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(tmp_path / "specs")
    assert str(caught.value) == f"spec file {tmp_path}/specs/env.yaml (a link to {secret}) {OUTSIDE}"


@pytest.mark.parametrize(
    ("element", "target"),
    [
        pytest.param(
            '<include file="../outside/part.xml"/>', "<include> file {tmp}/outside/part.xml", id="include"
        ),
        pytest.param(
            '<worldbody><flexcomp name="f" type="mesh" dim="2" file="../outside/tetra.obj"/></worldbody>',
            "<flexcomp> file {tmp}/outside/tetra.obj",
            id="flexcomp-mesh",
        ),
    ],
)
def test_files_read_while_parsing_are_confined_too(
    write: Write, tmp_path: Path, element: str, target: str
) -> None:
    write("outside/part.xml", "<mujoco/>")
    write("outside/tetra.obj", TETRAHEDRON_OBJ)
    write("specs/twolink.xml", TWO_LINK_MJCF.replace("<worldbody>", f"{element}\n  <worldbody>", 1))
    (cls,) = assembler.register_specs(write("specs/arm.yaml", "name: Arm\nmjcf: twolink.xml\n"))
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == (
        f"{tmp_path}/specs/arm.yaml:2:7: mjcf: {tmp_path}/specs/twolink.xml: "
        f"{target.format(tmp=tmp_path)} {OUTSIDE}"
    )


BILLION_LAUGHS = """\
<?xml version="1.0"?>
<!DOCTYPE mujoco [
  <!ENTITY a "aaaaaaaaaa">
  <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
  <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">
  <!ENTITY d "&c;&c;&c;&c;&c;&c;&c;&c;&c;&c;">
]>
<mujoco model="&d;"><worldbody/></mujoco>
"""
EXTERNAL_ENTITY = """\
<?xml version="1.0"?>
<!DOCTYPE mujoco [<!ENTITY secret SYSTEM "file:///etc/hostname">]>
<mujoco model="&secret;"><worldbody/></mujoco>
"""


@pytest.mark.parametrize(
    "text", [BILLION_LAUGHS, EXTERNAL_ENTITY], ids=["entity-expansion", "external-entity"]
)
def test_mjcf_with_a_doctype_is_refused_before_parsing(write: Write, tmp_path: Path, text: str) -> None:
    write("specs/bomb.xml", text)
    (cls,) = assembler.register_specs(write("specs/bomb.yaml", "name: Bomb\nmjcf: bomb.xml\n"))
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == (
        f"{tmp_path}/specs/bomb.yaml:2:7: mjcf: {tmp_path}/specs/bomb.xml: a document type declaration "
        "(<!DOCTYPE ...>) is not allowed in MJCF: XML entities are declared there and their expansion "
        "is unbounded; remove it"
    )


def test_shipped_specs_build_from_another_working_directory(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.chdir(tmp_path)  # the shipped specs reach ../../assets: the shipped assets folder
    assert _build(["build", "Sparrow7", "--base", "QuadrupedBase", "-o", "out.xml"], capsys) == (
        0,
        ["wrote out.xml"],
    )


def test_a_controller_file_a_spec_names_is_confined_too(write: Write, tmp_path: Path) -> None:
    pytest.importorskip("robosuite")
    controllers = importlib.import_module("assembler.robosuite.controllers")  # imports robosuite
    write("outside/ctrl.json", '{"type": "BASIC", "body_parts": {}}')
    write("specs/twolink.xml", TWO_LINK_MJCF)
    spec = write(
        "specs/arm.yaml", "name: Arm\nmjcf: twolink.xml\nrobosuite:\n  controller: ../outside/ctrl.json\n"
    )
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(SpecError) as caught:
        controllers.declared_config(cls)
    assert str(caught.value) == f"{spec}:4:15: robosuite.controller: {tmp_path}/outside/ctrl.json {OUTSIDE}"


def test_mjcf_declaring_an_unknown_encoding_is_one_line(write: Write, tmp_path: Path) -> None:
    # expat raises LookupError, not ExpatError, for it: a traceback before issue 23.
    write("specs/enc.xml", '<?xml version="1.0" encoding="no-such"?>\n' + TWO_LINK_MJCF)
    (cls,) = assembler.register_specs(write("specs/enc.yaml", "name: Enc\nmjcf: enc.xml\n"))
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == (
        f"{tmp_path}/specs/enc.yaml:2:7: mjcf: {tmp_path}/specs/enc.xml: not well-formed XML: "
        "unknown encoding: no-such"
    )


@pytest.mark.parametrize("folder", [".", "robot"], ids=["mjcf-in-the-working-folder", "mjcf-in-a-folder"])
def test_an_asset_refusal_names_the_mjcf_file_not_its_folder(
    folder: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """Found by the hostile-input battery: the refusal named '.' (the MJCF's folder, the working one)."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / folder).mkdir(exist_ok=True)
    (tmp_path / folder / "meshy.xml").write_text(MESH_MJCF.format(meshdir=".", file="/etc/hostname.obj"))
    (tmp_path / "meshy.yaml").write_text(f"name: Meshy\nmjcf: {folder}/meshy.xml\n")
    assert main(["build", "meshy.yaml"]) == 1
    mjcf = "meshy.xml" if folder == "." else "robot/meshy.xml"
    assert (
        capsys.readouterr().err == f"meshy.yaml:2:7: mjcf: {mjcf}: asset file /etc/hostname.obj {OUTSIDE}\n"
    )
