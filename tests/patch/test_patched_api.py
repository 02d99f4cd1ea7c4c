"""``assemble(robot, overrides=...).get_model()`` with the plain robot cached: patched, not compiled, and
equal to the full compile in every model field; ``get_xml()`` and ``save()`` with the plain robot's XML
cached: its text with the values written in, which MuJoCo loads to the full compile's model; a
structural override is compiled, with the reason."""

from __future__ import annotations

import logging
import os
import time
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

import assembler
from assembler.compiler import service
from assembler.compiler.service import wait_for_writes
from tests.conftest import use_private_cache
from tests.models.test_physical import CUBE_OBJ, MESH_MJCF
from tests.patch.test_patchable import CASES, Write, _model_arrays, _register_declared


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    return use_private_cache(tmp_path / "cache", monkeypatch)


def _settled(folder: Path) -> None:
    """Date every file under ``folder`` ten seconds back: the cache keeps no model made from files
    modified in the last seconds (tests/cache/test_cache.py's ``edit`` does the same)."""
    then = time.time() - 10
    for path in folder.rglob("*"):
        if path.is_file():
            os.utime(path, (then, then))


def _no_compile(monkeypatch: pytest.MonkeyPatch) -> None:
    """From here on, a compile or a mesh decode in this process fails the test."""

    def refuse(*_: object) -> None:
        raise AssertionError("compiled or decoded a mesh")

    for name in ("compile_from_store", "compile_spec", "compile_with_home"):
        monkeypatch.setattr(f"assembler.compiler.compile.{name}", refuse)
    monkeypatch.setattr("assembler.cache.mesh_data.decode", refuse)
    monkeypatch.setattr("assembler.cache.mesh_fill.decode", refuse)


def _differences(ours: Any, theirs: Any) -> list[str]:
    a, b = _model_arrays(ours), _model_arrays(theirs)
    assert a.keys() == b.keys()
    return [
        name
        for name in b
        if a[name].shape != b[name].shape or not np.allclose(a[name], b[name], rtol=1e-10, atol=1e-10)
    ]


def _asked_with_the_plain_robot_cached(
    write: Write,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    robot: str,
    overrides: dict[str, Any],
    xml: bool,
) -> tuple[mujoco.MjModel, mujoco.MjModel, int]:
    """The variant's model (with ``xml``, its ``get_xml()`` reloaded) asked for with the plain robot
    (and its XML) cached and compiles and mesh decodes forbidden; its full compile; and how many
    answers were patched meanwhile."""
    _register_declared(write)
    _settled(tmp_path)
    compiled = assembler.assemble(robot, overrides=overrides).get_model(cache=False, store=False)
    if xml:
        assembler.assemble(robot).get_xml()  # the plain robot's model and XML in the cache
    else:
        assembler.assemble(robot).get_model()
    wait_for_writes()
    patched_before = service.counts.patched
    with monkeypatch.context() as tripwire:
        _no_compile(tripwire)
        variant = assembler.assemble(robot, overrides=overrides)
        model = mujoco.MjModel.from_xml_string(variant.get_xml()) if xml else variant.get_model()
    return model, compiled, service.counts.patched - patched_before


WRITTEN_CASES = [(robot, overrides) for robot, overrides in CASES if "bodies" not in overrides]
"""The variants whose XML is the plain robot's with attributes rewritten (bodies: scales change
several attributes of several elements, and are compiled)."""

ASKED = [(*case, False) for case in CASES] + [(*case, True) for case in WRITTEN_CASES]
"""Every case by ``get_model()``, and each written case by ``get_xml()`` (its text reloaded)."""


@pytest.mark.parametrize(
    ("robot", "overrides", "xml"),
    ASKED,
    ids=[f"{'get_xml' if xml else 'get_model'}-{next(iter(o))}-{i}" for i, (_, o, xml) in enumerate(ASKED)],
)
def test_a_variant_of_a_cached_robot_is_patched_or_its_xml_edited_and_equals_its_full_compile(
    write: Write,
    tmp_path: Path,
    monkeypatch: pytest.MonkeyPatch,
    robot: str,
    overrides: dict[str, Any],
    xml: bool,
) -> None:
    model, compiled, patched = _asked_with_the_plain_robot_cached(
        write, tmp_path, monkeypatch, robot, overrides, xml
    )
    assert patched == 1
    assert _differences(model, compiled) == []


SCALED_CASES = [(robot, overrides) for robot, overrides in CASES if "bodies" in overrides]


@pytest.mark.parametrize(
    ("robot", "overrides"),
    SCALED_CASES,
    ids=[next(iter(o["bodies"][0])) + f"-{i}" for i, (_, o) in enumerate(SCALED_CASES)],
)
def test_the_xml_of_a_scaled_variant_reloads_to_the_model_it_was_compiled_to(
    write: Write, robot: str, overrides: dict[str, Any]
) -> None:
    """A site's sizes its type does not read (a sphere's second and third) are not written to the XML,
    so a size_scale leaves them: else the model reloaded from get_xml() differs from get_model()'s."""
    _register_declared(write)
    xml = assembler.assemble(robot, overrides=overrides).get_xml(cache=False, store=False)
    compiled = assembler.assemble(robot, overrides=overrides).get_model(cache=False, store=False)
    assert _differences(mujoco.MjModel.from_xml_string(xml), compiled) == []


def test_the_xml_of_a_variant_with_a_body_scale_is_compiled(caplog: pytest.LogCaptureFixture) -> None:
    assembler.assemble("Sparrow7").get_xml()
    wait_for_writes()
    patched = service.counts.patched
    overrides = {"bodies": [{"match": "link3", "mass_scale": 1.4}]}
    with caplog.at_level(logging.DEBUG, logger="assembler.patch.robot_variant"):
        xml = assembler.assemble("Sparrow7", overrides=overrides).get_xml()
    assert service.counts.patched == patched
    compiled = assembler.assemble("Sparrow7", overrides=overrides).get_model(cache=False, store=False)
    assert _differences(mujoco.MjModel.from_xml_string(xml), compiled) == []
    plain = assembler.assemble("Sparrow7").get_model()
    scaled = mujoco.MjModel.from_xml_string(xml).body("robot0_link3").mass[0]
    assert scaled == pytest.approx(1.4 * plain.body("robot0_link3").mass[0])
    assert "Sparrow70 compiled for its XML: not writable as attribute edits" in caplog.text


def test_the_xml_of_a_body_scaled_variant_of_a_robot_not_cached_is_one_compile(private_cache: Path) -> None:
    overrides = {"bodies": [{"match": "link3", "mass_scale": 1.4}]}
    xml = assembler.assemble("Sparrow7", overrides=overrides).get_xml()
    wait_for_writes()
    assert len(list(private_cache.glob("*.json"))) == 1  # the variant's entry: no plain robot compiled first
    scaled = mujoco.MjModel.from_xml_string(xml).body("robot0_link3").mass[0]
    plain = assembler.assemble("Sparrow7").get_model()
    assert scaled == pytest.approx(1.4 * plain.body("robot0_link3").mass[0])


def test_a_saved_variant_of_a_cached_robot_is_written_without_a_compile_and_loads(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    overrides = {"joint_defaults.damping": 0.45, "init_qpos": [0.2, -0.4, 0.0, -1.9, 0.0, 1.3, 0.5]}
    compiled = assembler.assemble("Sparrow7", overrides=overrides).get_model(cache=False, store=False)
    assembler.assemble("Sparrow7").save(tmp_path / "plain.xml")
    wait_for_writes()
    with monkeypatch.context() as tripwire:
        _no_compile(tripwire)
        saved = assembler.assemble("Sparrow7", overrides=overrides).save(tmp_path / "variant.xml")
    loaded = mujoco.MjModel.from_xml_path(str(saved))
    assert _differences(loaded, compiled) == []
    assert loaded.key("home").qpos[:7].tolist() == overrides["init_qpos"]  # the arm's; then the fingers


HELD = ("nothing", "the plain model", "the plain model and XML", "the variant")
"""What the cache holds when a variant's XML is asked for (each a fresh cache); last, with the cache off."""


def _variant_xml(held: str, overrides: dict[str, Any], monkeypatch: pytest.MonkeyPatch, folder: Path) -> str:
    use_private_cache(folder, monkeypatch)
    if held == "the plain model":
        assembler.assemble("Sparrow7").get_model()
    elif held == "the plain model and XML":
        assembler.assemble("Sparrow7").get_xml()
    elif held == "the variant":
        assembler.assemble("Sparrow7", overrides=overrides).get_xml()
    wait_for_writes()
    return assembler.assemble("Sparrow7", overrides=overrides).get_xml()


def test_the_xml_of_a_variant_is_the_same_whatever_the_cache_holds(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A written file's bytes depend on the overrides, never on the cache: a servo's damping ratio
    patched stays a ratio where a compile writes the kv it resolves to, so a file made once from the
    cache and once by a compile would differ in review though both load to the same model."""
    overrides = {"joints": [{"match": "joint2", "armature": 0.3}]}  # moves the servos' resolved kv
    texts = {
        held: _variant_xml(held, overrides, monkeypatch, tmp_path / str(i)) for i, held in enumerate(HELD)
    }
    texts["the cache off"] = assembler.assemble("Sparrow7", overrides=overrides).get_xml(cache=False)
    assert len(set(texts.values())) == 1, {held: hash(text) for held, text in texts.items()}
    compiled = assembler.assemble("Sparrow7", overrides=overrides).get_model(cache=False, store=False)
    assert _differences(mujoco.MjModel.from_xml_string(texts["nothing"]), compiled) == []


def test_the_xml_of_a_variant_asked_again_is_answered_from_the_cache(monkeypatch: pytest.MonkeyPatch) -> None:
    overrides = {"joint_defaults.damping": 0.25}
    first = assembler.assemble("Sparrow7", overrides=overrides).get_xml()
    wait_for_writes()
    with monkeypatch.context() as tripwire:
        _no_compile(tripwire)
        again = assembler.assemble("Sparrow7", overrides=overrides).get_xml()
    assert again == first
    assert mujoco.MjModel.from_xml_string(again).joint("robot0_joint1").damping[0] == pytest.approx(0.25)


def test_a_patched_variant_is_not_stored_and_asked_again_is_patched_again(
    private_cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    overrides = {"joint_defaults.frictionloss": 0.07}
    assembler.assemble("Sparrow7").get_model()
    wait_for_writes()
    entries = sorted(private_cache.glob("*.mjb"))
    first = assembler.assemble("Sparrow7", overrides=overrides).get_model()
    wait_for_writes()
    assert sorted(private_cache.glob("*.mjb")) == entries  # only the plain robot's entry
    patched = service.counts.patched
    with monkeypatch.context() as tripwire:
        _no_compile(tripwire)
        again = assembler.assemble("Sparrow7", overrides=overrides).get_model()
    assert service.counts.patched == patched + 1
    assert np.array_equal(again.dof_frictionloss, first.dof_frictionloss)
    assert again.joint("robot0_joint2").frictionloss[0] == pytest.approx(0.07)


TAMPERED = {
    "cut short": lambda text: text[: len(text) // 2],
    "not a model field": lambda text: text.replace('"dof_frictionloss"', '"__class__"'),
    "a value of another shape": lambda text: text.replace("0.07]", "[0.07, 0.07, 0.07]]"),
    "another source": lambda text: text.replace('"source": "', '"source": "0'),
}


@pytest.mark.parametrize("tamper", TAMPERED)
def test_a_kept_patch_that_is_not_whole_is_a_miss_and_the_variant_patched_again(
    private_cache: Path, tamper: str
) -> None:
    overrides = {"joint_defaults.frictionloss": 0.07}
    assembler.assemble("Sparrow7").get_model()
    wait_for_writes()
    first = assembler.assemble("Sparrow7", overrides=overrides).get_model()
    [kept] = private_cache.glob("*.patch")
    text = kept.read_text()
    kept.write_text(TAMPERED[tamper](text))
    assert kept.read_text() != text
    again = assembler.assemble("Sparrow7", overrides=overrides).get_model()
    assert _differences(again, first) == []
    assert kept.read_text() == text  # worked out again and kept again


def test_a_structural_override_is_compiled_and_the_reason_is_logged(
    caplog: pytest.LogCaptureFixture,
) -> None:
    assembler.assemble("Sparrow7").get_model()
    wait_for_writes()
    patched = service.counts.patched
    with caplog.at_level(logging.DEBUG, logger="assembler.patch.robot_variant"):
        model = assembler.assemble("Sparrow7", overrides={"remove_free_joint": True}).get_model()
    assert service.counts.patched == patched
    assert model.nbody > 0
    assert "Sparrow70 compiled: remove_free_joint: not a patchable field" in caplog.text


def test_a_variant_of_a_robot_not_in_the_cache_is_compiled_and_says_why(
    caplog: pytest.LogCaptureFixture,
) -> None:
    patched = service.counts.patched
    with caplog.at_level(logging.DEBUG, logger="assembler.patch.robot_variant"):
        model = assembler.assemble("Finch6", overrides={"joint_defaults.damping": 0.2}).get_model()
    assert service.counts.patched == patched
    assert model.joint("robot0_joint1").damping[0] == pytest.approx(0.2)
    assert "the robot without its overrides is not in the model cache" in caplog.text


def test_api_joint_edits_are_compiled_not_patched() -> None:
    assembler.assemble("Sparrow7").get_model()
    wait_for_writes()
    robot = assembler.assemble("Sparrow7", overrides={"joint_defaults.damping": 0.3})
    robot.set_joint_attribute("armature", np.full(7, 0.2))
    patched = service.counts.patched
    model = robot.get_model()
    assert service.counts.patched == patched
    assert model.joint("robot0_joint4").armature[0] == pytest.approx(0.2)


def test_a_robot_with_meshes_is_patched_without_reading_or_decoding_a_mesh(
    write: Write, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write("m/block.obj", CUBE_OBJ)
    write("m/meshy.xml", MESH_MJCF)
    assembler.register_specs(write("m/meshy.yaml", "name: Meshy\nmjcf: meshy.xml\n"))
    _settled(tmp_path)
    overrides = {"joint_defaults.damping": 0.8, "geoms": [{"match": "*", "friction": [0.4, 0.01, 0.002]}]}
    compiled = assembler.assemble("Meshy", overrides=overrides).get_model(cache=False, store=False)
    assembler.assemble("Meshy").get_model()
    wait_for_writes()
    with monkeypatch.context() as tripwire:
        _no_compile(tripwire)
        model = assembler.assemble("Meshy", overrides=overrides).get_model()
    assert model.nmesh > 0 and np.array_equal(model.mesh_vert, compiled.mesh_vert)
    assert _differences(model, compiled) == []
