"""Spec repositories: a checkout that declares itself lets its specs read its own spec and asset
folders (specs/ beside assets/, the README's layout) and nothing more; the same spec registered
from two places is one spec, two different specs of one name are still an error naming both."""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from assembler.errors import MjcfError, RegistryError, SpecError
from assembler.files.paths import ALLOW_VARIABLE, shipped_assets_dir, shipped_specs_dir
from assembler.registry.lookup import REGISTERED_ROBOTS
from tests.conftest import TETRAHEDRON_OBJ, TWO_LINK_MJCF
from tests.files.test_confinement import MESH_MJCF, OUTSIDE

Write = Callable[[str, str], Path]

ARM = "name: Arm\nmjcf: ../assets/arm/twolink.xml\n"
"""A spec in specs/ naming its MJCF in assets/, as the README's layout has it."""

TABLE = '[project]\nname = "lab-robots"\n\n[tool.robot-assembler]\nspecs = ["specs"]\nassets = ["assets"]\n'


@pytest.fixture(autouse=True)
def no_allowed_paths(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(ALLOW_VARIABLE, raising=False)


def lab(write: Write, declaration: tuple[str, str] | None = ("robot-assembler.toml", "")) -> Path:
    """A lab's checkout at tmp/lab: specs/arm.yaml, assets/arm/twolink.xml, .git, and a declaration."""
    write("lab/assets/arm/twolink.xml", TWO_LINK_MJCF)
    spec = write("lab/specs/arm.yaml", ARM)
    (spec.parent.parent / ".git").mkdir()
    if declaration is not None:
        write(f"lab/{declaration[0]}", declaration[1])
    return spec


@pytest.mark.parametrize(
    "declaration",
    [
        pytest.param(("robot-assembler.toml", ""), id="empty-marker-file"),
        pytest.param(("robot-assembler.toml", 'specs = ["specs"]\nassets = ["assets"]\n'), id="marker-file"),
        pytest.param(("pyproject.toml", TABLE), id="pyproject-table"),
    ],
)
def test_a_spec_in_a_declared_repository_reads_its_assets(write: Write, declaration: tuple[str, str]) -> None:
    (cls,) = assembler.register_specs(lab(write, declaration))
    assert cls(idn=0).get_model().njnt == 2


def test_an_undeclared_checkout_is_refused_with_how_to_declare_it(write: Write, tmp_path: Path) -> None:
    spec = lab(write, declaration=None)
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == (
        f"{spec}:2:7: mjcf: {tmp_path}/lab/assets/arm/twolink.xml {OUTSIDE}, or declare the checkout "
        f"{tmp_path}/lab a spec repository (an empty robot-assembler.toml at its root lets its specs "
        "read its specs/ and assets/ folders; README: Spec repositories)"
    )


def test_a_pyproject_without_the_table_declares_nothing(write: Write) -> None:
    spec = lab(write, ("pyproject.toml", '[project]\nname = "lab-robots"\n'))
    with pytest.raises(SpecError, match="or declare the checkout"):
        assembler.register_specs(spec)


def test_a_spec_outside_any_repository_still_reads_only_its_folder(write: Write, tmp_path: Path) -> None:
    write("assets/arm/twolink.xml", TWO_LINK_MJCF)
    spec = write("specs/arm.yaml", ARM)
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == f"{spec}:2:7: mjcf: {tmp_path}/assets/arm/twolink.xml {OUTSIDE}"


def test_a_declaration_above_the_checkout_is_not_its_own(write: Write, tmp_path: Path) -> None:
    write("robot-assembler.toml", 'allow = ["lab"]\n')  # tmp/ declares, tmp/lab/.git is the checkout
    spec = lab(write, declaration=None)
    with pytest.raises(SpecError, match="or declare the checkout"):
        assembler.register_specs(spec)


def test_the_repository_opens_only_the_folders_it_names(write: Write, tmp_path: Path) -> None:
    write("lab/secrets/tetra.obj", TETRAHEDRON_OBJ)
    write("lab/assets/arm/meshy.xml", MESH_MJCF.format(meshdir="../../secrets", file="tetra.obj"))
    spec = write("lab/specs/meshy.yaml", "name: Meshy\nmjcf: ../assets/arm/meshy.xml\n")
    marker = write("lab/robot-assembler.toml", "")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == (
        f"{spec}:2:7: mjcf: {tmp_path}/lab/assets/arm/meshy.xml: asset file {tmp_path}/lab/secrets/tetra.obj is "
        "outside the folders a spec may read (its own folder, the folders its spec repository declares, "
        "the shipped specs and assets, installed packages); pass --allow-path DIR (or set "
        f"ASSEMBLER_ALLOW_PATHS) to allow it, or name its folder in allow of {marker}"
    )
    marker.write_text('allow = ["secrets"]\n')
    (cls,) = assembler.register_specs(spec)
    assert cls(idn=0).get_model().nmesh == 1


@pytest.mark.parametrize(
    ("text", "message"),
    [
        pytest.param(
            'allow = [".."]\n',
            "{marker}: allow: '..' leads to {tmp}, outside the repository {tmp}/lab; a spec repository may "
            "only open its own folders to its specs",
            id="dotdot",
        ),
        pytest.param(
            'assets = ["assets/../../outside"]\n',
            "{marker}: assets: 'assets/../../outside' leads to {tmp}/outside, outside the repository "
            "{tmp}/lab; a spec repository may only open its own folders to its specs",
            id="dotdot-inside-a-name",
        ),
        pytest.param(
            'allow = ["/etc"]\n',
            "{marker}: allow: '/etc' is not a folder relative to the repository; name folders inside it, "
            "relative to its root",
            id="absolute",
        ),
        pytest.param(
            'allow = ["exit"]\n',
            "{marker}: allow: 'exit' leads to {tmp}/outside, outside the repository {tmp}/lab; a spec "
            "repository may only open its own folders to its specs",
            id="link-leading-out",
        ),
        pytest.param(
            'allow = ["nope"]\n',
            "{marker}: allow: 'nope' is not a folder of the repository {tmp}/lab",
            id="missing-folder",
        ),
        pytest.param(
            'allow = "assets"\n',
            '{marker}: allow must be a list of folder names, e.g. allow = ["meshes"]',
            id="not-a-list",
        ),
        pytest.param(
            'packages = "vendor"\n',
            '{marker}: packages must be a list of folder names, e.g. packages = ["vendor/z1_description"]',
            id="packages-not-a-list",
        ),
        pytest.param(
            'packages = ["exit"]\n',
            "{marker}: packages: 'exit' leads to {tmp}/outside, outside the repository {tmp}/lab; a spec "
            "repository may only open its own folders to its specs",
            id="package-linking-out",
        ),
        pytest.param(
            'allow = [".git"]\n',
            "{marker}: allow: '.git' is inside the checkout's .git folder, which a spec may never read; "
            "name other folders",
            id="the-git-folder",
        ),
        pytest.param(
            'allow = [".git/objects"]\n',
            "{marker}: allow: '.git/objects' is inside the checkout's .git folder, which a spec may never "
            "read; name other folders",
            id="inside-the-git-folder",
        ),
        pytest.param(
            'alow = ["assets"]\n',
            "{marker}: unknown key 'alow'. Did you mean 'allow'? Valid keys: specs, assets, allow, packages",
            id="unknown-key",
        ),
    ],
)
def test_a_declaration_reaching_outside_its_repository_is_refused(
    write: Write, tmp_path: Path, text: str, message: str
) -> None:
    spec = lab(write, ("robot-assembler.toml", text))
    (tmp_path / "outside").mkdir()
    (tmp_path / "lab" / "exit").symlink_to(tmp_path / "outside")
    marker = tmp_path / "lab" / "robot-assembler.toml"
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == f"{spec}:2:7: mjcf: " + message.format(marker=marker, tmp=tmp_path)


def test_a_default_folder_that_links_out_of_the_repository_is_refused(write: Write, tmp_path: Path) -> None:
    write("outside/arm/twolink.xml", TWO_LINK_MJCF)
    spec = write("lab/specs/arm.yaml", ARM)
    marker = write("lab/robot-assembler.toml", "")
    (tmp_path / "lab" / "assets").symlink_to(tmp_path / "outside")
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == (
        f"{spec}:2:7: mjcf: {marker}: assets: 'assets' leads to {tmp_path}/outside, outside the repository "
        f"{tmp_path}/lab; a spec repository may only open its own folders to its specs"
    )


def test_broken_toml_is_one_line_naming_the_file(write: Write, tmp_path: Path) -> None:
    spec = lab(write, ("robot-assembler.toml", "allow = [\n"))
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    (problem,) = caught.value.problems
    assert str(problem).startswith(f"{spec}:2:7: mjcf: {tmp_path}/lab/robot-assembler.toml: not valid TOML: ")


def test_a_spec_reached_through_a_link_belongs_to_the_repository_it_really_lies_in(
    write: Write, tmp_path: Path
) -> None:
    spec = lab(write, declaration=None)  # the real checkout is undeclared
    write("other/robot-assembler.toml", "")
    (tmp_path / "other" / "specs").symlink_to(spec.parent)
    with pytest.raises(SpecError, match="or declare the checkout"):
        assembler.register_specs(tmp_path / "other" / "specs" / "arm.yaml")


def test_a_scene_in_the_repository_names_robot_specs_of_its_spec_folder(write: Write, tmp_path: Path) -> None:
    lab(write)
    scene = write("lab/scenes/pair.yaml", "kind: scene\nname: pair\nrobots:\n  - robot: ../specs/arm.yaml\n")
    out = tmp_path / "scene.xml"
    assert main(["scene", str(scene), "-o", str(out)]) == 0
    assert out.is_file()


def test_the_cli_validates_a_declared_repository_from_its_root(
    write: Write, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    lab(write)
    monkeypatch.chdir(tmp_path / "lab")
    assert main(["validate", "specs/", "--compile"]) == 0
    assert capsys.readouterr().out == "1 spec(s) validated and compiled: Arm\n"


# ----- the same spec from two places ------------------------------------------------------------


def shipped_copy(tmp_path: Path) -> Path:
    """A clone's specs/sparrow7.yaml and assets/sparrow7/: the shipped files, copied."""
    clone = tmp_path / "clone"
    shutil.copytree(shipped_assets_dir() / "sparrow7", clone / "assets" / "sparrow7")
    (clone / "specs").mkdir()
    shutil.copy(shipped_specs_dir() / "sparrow7.yaml", clone / "specs" / "sparrow7.yaml")
    (clone / "robot-assembler.toml").write_text("")
    return clone / "specs" / "sparrow7.yaml"


def test_a_clones_copy_of_a_shipped_spec_is_the_same_spec_and_takes_its_place(tmp_path: Path) -> None:
    copy = shipped_copy(tmp_path)
    (cls,) = assembler.register_specs(copy)
    assert REGISTERED_ROBOTS["Sparrow7"] is cls
    assert cls.loaded is not None and cls.loaded.document.path == copy
    assert assembler.assemble("Sparrow7").get_model().nu > 7  # with its pedestal and gripper


def test_a_changed_copy_of_a_shipped_spec_is_a_different_spec(tmp_path: Path) -> None:
    copy = shipped_copy(tmp_path)
    copy.write_text(copy.read_text().replace("damping: 0.1", "damping: 0.2"))
    with pytest.raises(RegistryError) as caught:
        assembler.register_specs(copy)
    shipped = shipped_specs_dir() / "sparrow7.yaml"
    assert str(caught.value).startswith(f"{copy}:")
    assert str(caught.value).endswith(
        f"name: robot 'Sparrow7' is already registered by {REGISTERED_ROBOTS['Sparrow7'].loaded.source} "  # type: ignore[union-attr]
        "(the installed package's copy; to change a shipped spec in a clone of robot-assembler, install "
        'the clone with pip install -e ".[robosuite]"), a different spec; rename one'
    )
    assert REGISTERED_ROBOTS["Sparrow7"].loaded.document.path == shipped.resolve()  # type: ignore[union-attr]


def test_a_copy_whose_mjcf_differs_is_a_different_spec(tmp_path: Path) -> None:
    copy = shipped_copy(tmp_path)
    mjcf = copy.parent.parent / "assets" / "sparrow7" / "sparrow7.xml"
    mjcf.write_text(mjcf.read_text().replace('damping="', 'damping="1', 1))
    with pytest.raises(RegistryError, match="a different spec; rename one"):
        assembler.register_specs(copy)


def test_the_same_spec_in_two_user_folders_registers_once(write: Write) -> None:
    write("robots/twolink.xml", TWO_LINK_MJCF)
    write("mirror/twolink.xml", TWO_LINK_MJCF)
    first = write("robots/twolink.yaml", "name: TwoLink\nmjcf: twolink.xml\n")
    second = write("mirror/twolink.yaml", "name: TwoLink\nmjcf: twolink.xml\n")
    assembler.register_specs(first)
    (cls,) = assembler.register_specs(second)
    assert REGISTERED_ROBOTS["TwoLink"] is cls and cls.loaded is not None
    assert cls.loaded.document.path == second


@pytest.mark.parametrize(
    ("manifests", "message"),
    [
        pytest.param(
            {
                "vendor/a": '<?xml version="1.0"?><!DOCTYPE p [<!ENTITY n "a">]><package><name>&n;</name></package>'
            },
            "{tmp}/lab/vendor/a/package.xml: a document type declaration (<!DOCTYPE ...>) is not allowed: "
            "XML entities are declared there and their expansion is unbounded; remove it",
            id="package-xml-with-a-doctype",
        ),
        pytest.param(
            {
                "vendor/a": "<package><name>arm</name></package>",
                "vendor/b": "<package><name>arm</name></package>",
            },
            "{marker}: packages: {tmp}/lab/vendor/a and {tmp}/lab/vendor/b are both package 'arm'; declare "
            "one of them",
            id="two-folders-of-one-package",
        ),
    ],
)
def test_a_declared_package_is_named_by_its_package_xml_read_safely(
    write: Write, tmp_path: Path, manifests: dict[str, str], message: str
) -> None:
    for folder, manifest in manifests.items():
        write(f"lab/{folder}/package.xml", manifest)
    declared = ", ".join(f'"{folder}"' for folder in manifests)
    spec = lab(write, ("robot-assembler.toml", f"packages = [{declared}]\n"))
    marker = tmp_path / "lab" / "robot-assembler.toml"
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    assert str(caught.value) == f"{spec}:2:7: mjcf: " + message.format(marker=marker, tmp=tmp_path)


GIT_REFUSAL = "is inside a .git folder, which a spec may never read (whatever a repository allows); name a file of the checkout itself"


@pytest.mark.parametrize(
    ("declaration", "spec_at", "mjcf", "refused"),
    [
        pytest.param('allow = ["."]\n', "lab/specs/git.yaml", "../.git/config", "lab/.git/config", id="allow-dot"),
        pytest.param("", "lab/git.yaml", ".git/config", "lab/.git/config", id="a-spec-beside-git"),
        pytest.param('allow = ["."]\n', "lab/specs/git.yaml", "../.git", "lab/.git", id="the-folder-itself"),
        pytest.param('allow = ["."]\n', "lab/specs/git.yaml", "../config-link", "lab/config-link (a link to {tmp}/lab/.git/config)", id="a-link-into-git"),
    ],
)  # fmt: skip
def test_no_spec_reads_the_git_folder_whatever_allow_says(
    write: Write, tmp_path: Path, declaration: str, spec_at: str, mjcf: str, refused: str
) -> None:
    lab(write, ("robot-assembler.toml", declaration))
    write("lab/.git/config", TWO_LINK_MJCF)  # an MJCF there would build: only the rule refuses it
    (tmp_path / "lab" / "config-link").symlink_to(".git/config")
    spec = write(spec_at, f"name: Git\nmjcf: {mjcf}\n")
    with pytest.raises(SpecError) as caught:
        assembler.register_specs(spec)
    shown = f"{tmp_path}/{refused}".format(tmp=tmp_path)
    assert str(caught.value) == f"{spec}:2:7: mjcf: {shown} {GIT_REFUSAL}"


def test_no_mesh_is_read_from_the_git_folder_whatever_allow_says(write: Write, tmp_path: Path) -> None:
    lab(write, ("robot-assembler.toml", 'allow = ["."]\n'))
    write("lab/.git/tetra.obj", TETRAHEDRON_OBJ)
    write("lab/assets/arm/meshy.xml", MESH_MJCF.format(meshdir="../../.git", file="tetra.obj"))
    spec = write("lab/specs/meshy.yaml", "name: Meshy\nmjcf: ../assets/arm/meshy.xml\n")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(MjcfError) as caught:
        cls(idn=0).check()
    assert str(caught.value) == (
        f"{spec}:2:7: mjcf: {tmp_path}/lab/assets/arm/meshy.xml: asset file {tmp_path}/lab/.git/tetra.obj "
        f"{GIT_REFUSAL}"
    )
