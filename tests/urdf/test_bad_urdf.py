"""A stranger's URDF in a lab's spec repository: every row gets its exact message, exit 1, no file.

Each row is a URDF (and the files around it) written into a checkout ``lab`` that declares itself a
spec repository, and the lines ``assembler build specs/arm.yaml -o out.xml`` prints from inside
``lab``. The rows are the cases of issue 23: ``package://`` names that are no package, paths out
of the allowed folders (the same line whether the file exists or not), mesh formats off the
allow-list and archives (never opened by trimesh), and every limit of a URDF.
"""

from __future__ import annotations

import io
import zipfile
from pathlib import Path

import mujoco
import pytest

import assembler.urdf.mesh_formats
from assembler.cli import main
from assembler.files.limits import MAX_URDF_DEPTH, MAX_URDF_LINKS
from assembler.urdf.mesh_formats import converter_available, importable
from tests.urdf.fixtures import dae_text, write_dae

INERTIAL = '<inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>'
TETRA = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
SPEC = "name: BadArm\nurdf: arm.urdf\neef_bodies: {right: l1}\n"
OUTSIDE = (
    "is outside the folders a spec may read (its own folder, the folders its spec repository declares, "
    "the shipped specs and assets, installed packages); pass --allow-path DIR (or set ASSEMBLER_ALLOW_PATHS) "
    "to allow it"
)
NOT_A_PACKAGE = (
    "not found (searched the packages its spec repository declares, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH and "
    "the share/ folders of this Python environment); declare its folder in packages of the spec "
    "repository's robot-assembler.toml (README: Spec repositories), or set ROS_PACKAGE_PATH or "
    "AMENT_PREFIX_PATH to where it is"
)
PACKAGE_OUTSIDE = OUTSIDE.replace("the folders its spec repository declares, ", "")
"""A package's files are confined to the package, not to the repository around it."""
FORMATS = "a mesh is STL, OBJ, MSH (read by MuJoCo) or DAE (COLLADA, converted to OBJ)"
HEAD = "specs/arm.yaml:2:7: urdf: specs/arm.urdf"
NEEDS_CONVERTER = pytest.mark.skipif(
    not (converter_available() and importable("collada")),
    reason='COLLADA meshes need trimesh and pycollada: pip install "robot-assembler[urdf]"',
)


def urdf(visual: str = "", joint: str = "", more: str = "") -> str:
    """Two links and a hinge, one element per line: the visual on line 3, the joint's end on 4."""
    return (
        '<robot name="bad">\n'
        f'  <link name="l0">{INERTIAL}</link>\n'
        f'  <link name="l1">{INERTIAL}{visual}</link>\n'
        '  <joint name="j1" type="revolute"><parent link="l0"/><child link="l1"/><axis xyz="0 0 1"/>'
        f'<limit lower="-1" upper="1"/>{joint}</joint>\n'
        f"{more}</robot>\n"
    )


def mesh(filename: str) -> str:
    return urdf(visual=f'<visual><geometry><mesh filename="{filename}"/></geometry></visual>')


def _zip() -> bytes:
    stream = io.BytesIO()
    with zipfile.ZipFile(stream, "w") as archive:
        archive.writestr("arm.dae", "<COLLADA/>")
    return stream.getvalue()


CHAIN = urdf(
    more="".join(f'  <link name="c{i}"/>\n' for i in range(MAX_URDF_LINKS))  # 2 + 1,000 links
)
JOINTS = urdf(
    more="".join(
        f'  <joint name="k{i}" type="fixed"><parent link="l0"/><child link="l1"/></joint>\n'
        for i in range(MAX_URDF_LINKS)
    )  # 1 + 1,000 joints
)
NESTED = urdf(visual="<visual>" * 5000 + "</visual>" * 5000)
VENDOR_PACKAGE: dict[str, str | bytes] = {
    "vendor/arm_pkg/package.xml": "<package><name>arm_pkg</name></package>",
    "vendor/arm_pkg/meshes/tetra.obj": TETRA,
    "vendor/arm_pkg/urdf/arm.urdf": mesh("package://arm_pkg/meshes/tetra.obj"),
}
"""A vendor's ROS package kept in the lab, its URDF naming its mesh through package://."""
ZERO_UNIT_DAE = dae_text(meter="0")
DOCTYPE_DAE = b'<?xml version="1.0"?>\n<!DOCTYPE c [<!ENTITY a "aaaa">]>\n<COLLADA>&a;</COLLADA>\n'

# One row per case: (URDF, other files of the lab, robot-assembler.toml, expected lines). {tmp}: the
# folder holding the lab.
# fmt: off
CASES = [
    # package:// names a real package root only
    pytest.param(mesh("package://lab/private/token.obj"), {"private/token.obj": TETRA}, "", [f"{HEAD}:3: mesh package://lab/private/token.obj: package 'lab' {NOT_A_PACKAGE}"], id="a-folder-named-like-the-package-is-no-package"),
    pytest.param(mesh("package://secret/token.obj"), {"private/package.xml": "<package><name>secret</name></package>", "private/token.obj": TETRA}, "", [f"{HEAD}:3: mesh package://secret/token.obj: package 'secret' {NOT_A_PACKAGE}"], id="a-package-xml-claiming-the-name-is-no-package"),
    pytest.param(mesh("package://arm_pkg/../private/token.obj"), {"vendor/arm_pkg/package.xml": "<package><name>arm_pkg</name></package>", "private/token.obj": TETRA}, 'packages = ["vendor/arm_pkg"]\n', [f"{HEAD}:3: mesh package://arm_pkg/../private/token.obj: vendor/private/token.obj {PACKAGE_OUTSIDE}"], id="dotdot-out-of-a-declared-package"),
    pytest.param(mesh("package://arm_pkg/../private/missing.obj"), {"vendor/arm_pkg/package.xml": "<package><name>arm_pkg</name></package>"}, 'packages = ["vendor/arm_pkg"]\n', [f"{HEAD}:3: mesh package://arm_pkg/../private/missing.obj: vendor/private/missing.obj {PACKAGE_OUTSIDE}"], id="dotdot-out-of-a-declared-package-to-a-missing-file"),
    pytest.param(mesh("x.obj"), {}, 'packages = ["../elsewhere"]\n', ["specs/arm.yaml:2:7: urdf: robot-assembler.toml: packages: '../elsewhere' leads to {tmp}/elsewhere, outside the repository {tmp}/lab; a spec repository may only open its own folders to its specs"], id="a-declared-package-outside-the-repository"),
    # the same line whether the file outside exists or not: no existence oracle
    pytest.param(mesh("../../outside/token.obj"), {"../outside/token.obj": TETRA}, "", [f"{HEAD}:3: mesh {{tmp}}/outside/token.obj {OUTSIDE}"], id="a-mesh-outside-that-exists"),
    pytest.param(mesh("../../outside/missing.obj"), {}, "", [f"{HEAD}:3: mesh {{tmp}}/outside/missing.obj {OUTSIDE}"], id="a-mesh-outside-that-does-not-exist"),
    # mesh formats are an allow-list, checked before any file is looked at
    pytest.param(mesh("file:///etc/passwd"), {}, "", [f"{HEAD}:3: mesh file:///etc/passwd: a file without a suffix is not a mesh format read here; {FORMATS}"], id="a-file-that-is-no-mesh"),
    pytest.param(mesh("meshes/arm.ply"), {"meshes/arm.ply": "ply\n"}, "", [f"{HEAD}:3: mesh meshes/arm.ply: '.ply' is not a mesh format read here; {FORMATS}"], id="a-format-off-the-list"),
    pytest.param(mesh("meshes/arm.zip"), {"meshes/arm.zip": _zip()}, "", [f"{HEAD}:3: mesh meshes/arm.zip: an archive (.zip) is not a mesh format read here; {FORMATS}"], id="zip"),
    pytest.param(mesh("meshes/arm.tar.gz"), {}, "", [f"{HEAD}:3: mesh meshes/arm.tar.gz: an archive (.tar.gz) is not a mesh format read here; {FORMATS}"], id="tar-gz"),
    pytest.param(mesh("meshes/arm.stl.bz2"), {}, "", [f"{HEAD}:3: mesh meshes/arm.stl.bz2: an archive (.bz2) is not a mesh format read here; {FORMATS}"], id="bz2"),
    pytest.param(mesh("meshes/arm.dae"), {"meshes/arm.dae": _zip()}, "", [f"{HEAD}:3: specs/meshes/arm.dae: an archive, not a COLLADA file; {FORMATS}"], id="a-zip-named-dae", marks=NEEDS_CONVERTER),
    pytest.param(mesh("meshes/arm.dae"), {"meshes/arm.dae": DOCTYPE_DAE}, "", [f"{HEAD}:3: specs/meshes/arm.dae: a document type declaration (<!DOCTYPE ...>) is not allowed: XML entities are declared there and their expansion is unbounded; remove it"], id="a-dae-with-a-doctype", marks=NEEDS_CONVERTER),
    pytest.param(mesh("meshes/arm.dae"), {"meshes/arm.dae": ZERO_UNIT_DAE}, "", [f"{HEAD}:3: specs/meshes/arm.dae: trimesh cannot convert it (Singular matrix)"], id="a-dae-in-units-of-zero-metres", marks=NEEDS_CONVERTER),
    pytest.param(mesh("meshes/arm.dae"), {"meshes/arm.dae": dae_text(meter="nan")}, "", [f"{HEAD}:3: specs/meshes/arm.dae: its coordinates are not finite numbers once in metres (a NaN or infinite <unit>, transform or vertex); fix the file"], id="a-dae-in-units-of-nan-metres", marks=NEEDS_CONVERTER),
    pytest.param('<?xml version="1.0" encoding="no-such"?>\n' + urdf(), {}, "", ["specs/arm.yaml:2:7: urdf: specs/arm.urdf: not well-formed XML: unknown encoding: no-such"], id="an-unknown-encoding"),
    # limits
    pytest.param(CHAIN, {}, "", [f"{HEAD}:{5 + MAX_URDF_LINKS - 2}: more than {MAX_URDF_LINKS} links, the limit (MuJoCo cannot compile a chain of bodies much deeper); a robot has a few dozen"], id="more-links-than-the-limit"),
    pytest.param(JOINTS, {}, "", [f"{HEAD}:{5 + MAX_URDF_LINKS - 1}: more than {MAX_URDF_LINKS} joints, the limit (MuJoCo cannot compile a chain of bodies much deeper); a robot has a few dozen"], id="more-joints-than-the-limit"),
    pytest.param(NESTED, {}, "", [f"{HEAD}:3: elements nest deeper than the limit of {MAX_URDF_DEPTH} levels; a URDF nests a few levels deep"], id="nested-visuals"),
    pytest.param(urdf(more='  <joint name="j1" type="fixed"><parent link="l0"/><child link="l1"/></joint>\n'), {}, "", [f"{HEAD}:5: a second joint named 'j1' (the first is on line 4); joint names must be unique"], id="two-joints-of-one-name"),
    pytest.param(urdf(more=f'  <link name="l1">{INERTIAL}</link>\n'), {}, "", [f"{HEAD}:5: a second link named 'l1' (the first is on line 3); link names must be unique"], id="two-links-of-one-name"),
]
# fmt: on


def _lab(tmp_path: Path, text: str, files: dict[str, str | bytes], declaration: str) -> Path:
    """The checkout ``tmp/lab`` (a spec repository) with ``specs/arm.yaml`` naming ``specs/arm.urdf``."""
    lab = tmp_path / "lab"
    for relative, content in {
        "robot-assembler.toml": declaration,
        "specs/arm.yaml": SPEC,
        "specs/arm.urdf": text,
        **{f"specs/{name}" if name.startswith("meshes/") else name: data for name, data in files.items()},
    }.items():
        path = lab / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        if isinstance(content, bytes):
            path.write_bytes(content)
        else:
            path.write_text(content)
    return lab


@pytest.fixture(autouse=True)
def no_ros_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    for variable in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH", "ASSEMBLER_ALLOW_PATHS"):
        monkeypatch.delenv(variable, raising=False)


@pytest.mark.parametrize(("text", "files", "declaration", "expected"), CASES)
def test_a_bad_urdf_gets_its_exact_message_and_writes_nothing(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
    text: str,
    files: dict[str, str | bytes],
    declaration: str,
    expected: list[str],
) -> None:
    monkeypatch.chdir(_lab(tmp_path, text, files, declaration))
    code = main(["build", "specs/arm.yaml", "-o", "out.xml"])
    captured = capsys.readouterr()
    assert (code, captured.err.splitlines()) == (1, [line.format(tmp=tmp_path) for line in expected])
    assert captured.out == ""
    assert not Path("out.xml").exists()


def test_a_urdf_reading_a_lab_file_through_a_folder_named_like_a_package_is_refused_and_bundles_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # The severe case of issue 23: package://lab/... used to mean "the folder above named lab".
    monkeypatch.chdir(
        _lab(tmp_path, mesh("package://lab/private/token.obj"), {"private/token.obj": TETRA}, "")
    )
    refusal = f"{HEAD}:3: mesh package://lab/private/token.obj: package 'lab' {NOT_A_PACKAGE}"
    assert main(["validate", "--compile", "specs/arm.yaml"]) == 1
    assert capsys.readouterr().err.splitlines() == [refusal]
    assert main(["build", "specs/arm.yaml", "--bundle", "bundle"]) == 1
    assert capsys.readouterr().err.splitlines() == [refusal]
    copied = [path.name for path in Path("bundle").rglob("*")] if Path("bundle").exists() else []
    assert copied == []


@pytest.mark.parametrize("target", ["etc/hostname", "etc/no-such-file"], ids=["existing", "missing"])
def test_a_spec_urdf_out_of_a_python_package_is_refused_alike_whether_or_not_it_exists(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], target: str
) -> None:
    reference = "package://numpy/" + "../" * 30 + target  # enough ".." to reach / from any site-packages
    lab = _lab(tmp_path, urdf(), {}, "")
    (lab / "specs" / "arm.yaml").write_text(SPEC.replace("urdf: arm.urdf", f"urdf: {reference}"))
    monkeypatch.chdir(lab)
    assert main(["build", "specs/arm.yaml", "-o", "out.xml"]) == 1
    assert capsys.readouterr().err.splitlines() == [
        f"specs/arm.yaml:2:7: urdf: {reference}: /{target} {PACKAGE_OUTSIDE}"
    ]


@pytest.mark.parametrize(
    "urdf_field",
    ["../vendor/arm_pkg/urdf/arm.urdf", "package://arm_pkg/urdf/arm.urdf"],
    ids=["by-path", "by-package-uri"],
)
def test_a_vendor_package_the_repository_declares_is_read_without_ros_package_path(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str], urdf_field: str
) -> None:
    lab = _lab(
        tmp_path,
        "",
        VENDOR_PACKAGE,
        'packages = ["vendor/arm_pkg"]\n',
    )
    (lab / "specs" / "arm.yaml").write_text(SPEC.replace("urdf: arm.urdf", f"urdf: {urdf_field}"))
    monkeypatch.chdir(lab)
    assert main(["build", "specs/arm.yaml", "-o", "out.xml"]) == 0
    assert capsys.readouterr().err == "wrote out.xml\n"
    model = mujoco.MjModel.from_xml_path("out.xml")
    assert model.nmesh == 1 and model.njnt == 1


def test_an_undeclared_vendor_package_beside_its_urdf_gets_the_line_that_declares_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # Before issue 23 such a package was found by its folder's name; now the refusal says what to write.
    lab = _lab(
        tmp_path,
        "",
        VENDOR_PACKAGE,
        'allow = ["vendor"]\n',
    )
    (lab / "specs" / "arm.yaml").write_text(SPEC.replace("arm.urdf", "../vendor/arm_pkg/urdf/arm.urdf"))
    monkeypatch.chdir(lab)
    assert main(["build", "specs/arm.yaml", "-o", "out.xml"]) == 1
    assert capsys.readouterr().err.splitlines() == [
        "specs/arm.yaml:2:7: urdf: vendor/arm_pkg/urdf/arm.urdf:3: mesh package://arm_pkg/meshes/tetra.obj: "
        "package 'arm_pkg' not found (searched the packages its spec repository declares, ROS_PACKAGE_PATH, "
        "AMENT_PREFIX_PATH and the share/ folders of this Python environment); if vendor/arm_pkg is that "
        'package, declare it: packages = ["vendor/arm_pkg"] in robot-assembler.toml, or set ROS_PACKAGE_PATH '
        "or AMENT_PREFIX_PATH to where it is"
    ]


@NEEDS_CONVERTER
def test_a_cache_folder_that_cannot_be_written_still_converts_a_dae_mesh(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    """A cache folder that cannot be made was a traceback (mkstemp); the converted mesh now goes to this
    process's own scratch folder, as with the cache off (assembler.cache.content)."""
    lab = _lab(tmp_path, mesh("meshes/arm.dae"), {}, "")
    write_dae(lab / "specs" / "meshes" / "arm.dae")
    (tmp_path / "cache").write_text("")  # a file where the folder should be: mkdir fails, also as root
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.chdir(lab)
    assert main(["validate", "--compile", "specs/arm.yaml"]) == 0
    assert "Traceback" not in capsys.readouterr().err
    assert (tmp_path / "cache").read_text() == ""  # the file in the cache folder's place is left alone


@NEEDS_CONVERTER
def test_a_dae_larger_than_the_limit_is_one_line_and_never_reaches_trimesh(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    lab = _lab(tmp_path, mesh("meshes/arm.dae"), {}, "")
    size = write_dae(lab / "specs" / "meshes" / "arm.dae").stat().st_size
    monkeypatch.setattr(assembler.urdf.mesh_formats, "MAX_DAE_BYTES", size - 1)  # 64 MiB is too much to write
    monkeypatch.chdir(lab)
    assert main(["validate", "--compile", "specs/arm.yaml"]) == 1
    assert capsys.readouterr().err.splitlines() == [
        f"{HEAD}:3: specs/meshes/arm.dae: the file's size exceeds the limit of {size - 1} bytes for a mesh"
    ]


@pytest.mark.filterwarnings("default::assembler.errors.AssemblerWarning")  # shown as the CLI shows it
def test_mujoco_extensions_a_urdf_gives_that_nothing_reads_are_said(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    extension = '  <mujoco><option timestep="0.001"/><actuator><motor joint="j1"/></actuator></mujoco>\n'
    monkeypatch.chdir(_lab(tmp_path, urdf(more=extension), {}, ""))
    assert main(["build", "specs/arm.yaml", "-o", "out.xml"]) == 0
    assert capsys.readouterr().err.splitlines() == [
        "warning: specs/arm.urdf:5: <mujoco><actuator> is ignored: a URDF's <mujoco> element gives only "
        "<compiler>, <option>, <size>, <visual>, <statistic>; say the rest in the spec (actuators:, joints:) "
        "or in an MJCF file",
        "wrote out.xml",
    ]
    model = mujoco.MjModel.from_xml_path("out.xml")
    assert model.opt.timestep == 0.001 and model.nu == 0  # <option> honoured, the motor not added


@pytest.mark.filterwarnings("default::assembler.errors.AssemblerWarning")  # shown as the CLI shows it
@pytest.mark.parametrize(
    ("shape", "shown"),
    [
        ('<sphere radius="0.0"/>', '<sphere radius="0.0">'),
        ('<box size="0.1 0 0.1"/>', '<box size="0.1 0 0.1">'),
        ('<cylinder radius="0.1" length="-1"/>', '<cylinder length="-1">'),
    ],
)
def test_a_visual_of_a_size_mujoco_cannot_compile_is_left_out_as_mujocos_import_leaves_it_out(
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    capsys: pytest.CaptureFixture[str],
    shape: str,
    shown: str,
) -> None:
    # pybullet's laikago_toes_zup.urdf marks its toes with <sphere radius="0.0"/>; MuJoCo loads it (it
    # discards visuals), so it is read, the visual left out and said
    visual = f"<visual><geometry>{shape}</geometry></visual>"
    monkeypatch.chdir(_lab(tmp_path, urdf(visual=visual), {}, ""))
    assert main(["build", "specs/arm.yaml", "-o", "out.xml"]) == 0
    assert capsys.readouterr().err.splitlines() == [
        f"warning: specs/arm.urdf:3: the <visual> of link 'l1' is {shown}, not a positive size: left out, as "
        "MuJoCo's URDF import leaves out every visual",
        "wrote out.xml",
    ]
    model = mujoco.MjModel.from_xml_path("out.xml")
    assert model.ngeom == 0


@pytest.mark.filterwarnings("default::assembler.errors.AssemblerWarning")  # shown as the CLI shows it
def test_a_number_that_is_not_finite_is_said_at_its_line_as_mujoco_keeps_it(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    # MuJoCo warns only that the file holds a NaN somewhere, and keeps it: a NaN position, an infinite size
    visual = '<visual><origin xyz="nan 0 0"/><geometry><box size="0.1 inf 0.1"/></geometry></visual>'
    monkeypatch.chdir(_lab(tmp_path, urdf(visual=visual), {}, ""))
    main(["validate", "--compile", "specs/arm.yaml"])
    err = capsys.readouterr().err.splitlines()
    for value in ('<origin xyz="nan 0 0">', '<box size="0.1 inf 0.1">'):
        assert (
            f"warning: specs/arm.urdf:3: {value} holds a value that is not a finite number: MuJoCo keeps it as written "
            "(a NaN position makes every step NaN, an infinite size a geom without bounds); correct the URDF"
        ) in err
