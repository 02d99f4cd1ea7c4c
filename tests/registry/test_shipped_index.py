"""The shipped specs are registered by name and each read when first looked up
(:mod:`assembler.registry.shipped`): a robot reads the specs it needs, a whole read of a table makes
every class, and a spec read alone is the spec the whole folder's batch gives."""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

from assembler.errors import RegistryError, SpecError
from assembler.files.paths import shipped_specs_dir
from assembler.models import REGISTRIES, ManipulatorModel
from assembler.registry import shipped
from assembler.registry.catalog import register_specs
from assembler.spec.spec_files import load_paths

REPOSITORY = Path(__file__).resolve().parents[2]


def _run(script: str) -> dict[str, object]:
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, cwd=REPOSITORY, check=False
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])  # type: ignore[no-any-return]


ONE_ROBOT = """\
import json
import assembler
from assembler.models import REGISTRIES
made = lambda: {family: sorted(dict.keys(table)) for family, table in REGISTRIES.items()}
from assembler.files.cache_location import cache_dir
panda = assembler.assemble("Panda")  # made now, and its request recorded for the next process
after_panda = made()
records = len(list((cache_dir() / "requests").iterdir()))
parts = {"base": type(panda.base).__name__, "grippers": sorted(type(g).__name__ for g in panda.grippers.values())}
sizes = {family: len(table) for family, table in REGISTRIES.items()}  # a whole read
print(json.dumps({"after_panda": after_panda, "parts": parts, "after_len": made(), "records": records}))
"""


def test_a_robot_reads_only_the_specs_it_is_made_of_and_a_whole_read_makes_them_all(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "cache"))  # no record yet: made now
    seen = _run(ONE_ROBOT)
    parts = seen["parts"]
    assert isinstance(parts, dict)
    assert seen["after_panda"] == {"robot": ["Panda"], "base": [parts["base"]], "gripper": parts["grippers"]}
    assert seen["records"] == 1  # recording the request did not need the other specs either
    batch = load_paths([shipped_specs_dir()])
    assert seen["after_len"] == {
        family: sorted(s.spec.name for s in batch if getattr(s.spec, "kind", "robot") == family)
        for family in REGISTRIES
    }


EACH_ALONE = """\
import json
from assembler.registry.catalog import PARENTS
from assembler.models import REGISTRIES
from assembler.registry import shipped
from assembler.files.paths import shipped_specs_dir
specs = {}
for (family, name) in sorted(shipped.scan(shipped_specs_dir())):
    specs[f"{family}/{name}"] = REGISTRIES[family][name].spec.model_dump(mode="json")
print(json.dumps(specs))
"""


def test_each_shipped_spec_read_alone_equals_the_folders_batch() -> None:
    alone = _run(EACH_ALONE)
    batch = {
        f"{getattr(s.spec, 'kind', 'robot')}/{s.spec.name}": s.spec.model_dump(mode="json")
        for s in load_paths([shipped_specs_dir()])
    }
    assert alone == batch


SAME_NAME_IN_PYTHON = """\
import json
from assembler.errors import RegistryError
from assembler.models import ManipulatorModel
import assembler.registry.catalog
try:
    class Panda(ManipulatorModel):
        pass
except RegistryError as error:
    print(json.dumps({"error": str(error)}))
else:
    print(json.dumps({"error": None}))
"""


def test_a_python_class_of_a_shipped_name_is_still_an_error_before_the_spec_is_read() -> None:
    error = _run(SAME_NAME_IN_PYTHON)["error"]
    assert isinstance(error, str) and "robot 'Panda' is defined twice" in error and "panda.yaml" in error


@pytest.mark.parametrize(
    ("text", "indexed"),
    [
        ("name: Arm\nmjcf: arm.xml\n", {("robot", "Arm")}),
        ("kind: gripper\nname: 'Hand'  # a comment\nmjcf: h.xml\n", {("gripper", "Hand")}),
        ("kind: scene\nname: Table\n", set()),  # a scene in the folder is not a part
        ("mjcf: arm.xml\n", None),  # no name line
        ("name: Arm\nname: Other\n", None),  # two
        ("name: >-\n  Arm\n", None),  # not a plain name
        ("kind: robott\nname: Arm\n", None),  # an unknown kind: the eager load reports it
    ],
)
def test_the_index_reads_plain_name_and_kind_lines_and_gives_up_on_anything_else(
    tmp_path: Path, text: str, indexed: set[tuple[str, str]] | None
) -> None:
    (tmp_path / "part.yaml").write_text(text)
    found = shipped.scan(tmp_path)
    assert (None if found is None else set(found)) == indexed


def test_a_name_defined_by_two_files_or_a_file_linked_from_outside_is_not_indexed(tmp_path: Path) -> None:
    folder, outside = tmp_path / "specs", tmp_path / "outside.yaml"
    folder.mkdir()
    (folder / "a.yaml").write_text("name: Arm\n")
    (folder / "b.yaml").write_text("name: Arm\n")
    assert shipped.scan(folder) is None
    (folder / "b.yaml").unlink()
    outside.write_text("name: Other\n")
    (folder / "b.yaml").symlink_to(outside)
    assert shipped.scan(folder) is None


def test_a_held_spec_that_does_not_load_reports_its_problem_at_every_lookup(
    write: Callable[[str, str], Path], monkeypatch: pytest.MonkeyPatch
) -> None:
    spec = write("specs/lazy_arm.yaml", "name: LazyArm\nmjcf: arm.xml\njoint_defaults: {damping: soft}\n")
    files = shipped.scan(spec.parent)
    assert files == {("robot", "LazyArm"): spec}
    index = shipped.ShippedIndex(files, lambda paths: register_specs(*paths))
    for table in REGISTRIES.values():
        monkeypatch.setattr(table, "unmade", index)
    for _ in range(2):
        with pytest.raises(SpecError, match=r"lazy_arm\.yaml:\d+:\d+"):
            REGISTRIES["robot"]["LazyArm"]
    spec.write_text(spec.read_text().replace("soft", "0.5"))
    (spec.parent / "arm.xml").write_text("<mujoco><worldbody/></mujoco>")
    made = REGISTRIES["robot"]["LazyArm"]
    assert issubclass(made, ManipulatorModel) and made.spec.joint_defaults.damping == 0.5
    assert not index.files
    with pytest.raises(RegistryError, match="unknown robot 'LazyArmm'. Did you mean"):
        REGISTRIES["robot"].lookup("LazyArmm")


THREADS = """\
import json, threading
from assembler.models import REGISTRIES
import assembler.registry.catalog
names = [("robot", "Panda"), ("robot", "GR1"), ("gripper", "PandaGripper"), ("base", "RethinkMount")] * 3
start, found, failed = threading.Barrier(len(names)), [], []
def look(family, name):
    start.wait()
    try:
        found.append(REGISTRIES[family][name].__name__)
    except Exception as error:
        failed.append(f"{name}: {error}")
threads = [threading.Thread(target=look, args=pair) for pair in names]
for thread in threads: thread.start()
for thread in threads: thread.join()
print(json.dumps({"found": sorted(found), "failed": failed}))
"""


def test_threads_looking_up_shipped_names_at_once_all_find_their_class() -> None:
    seen = _run(THREADS)
    assert seen["failed"] == []
    assert seen["found"] == sorted(["Panda", "GR1", "PandaGripper", "RethinkMount"] * 3)


WRITTEN_OVER = """\
import json
from assembler.models import REGISTERED_ROBOTS, ManipulatorModel
import assembler.registry.catalog
class MyPanda(ManipulatorModel):
    in_registry = False
REGISTERED_ROBOTS["Panda"] = MyPanda  # robosuite's way: an assignment, not register()
print(json.dumps({"looked_up": REGISTERED_ROBOTS["Panda"].__name__, "listed": "Panda" in list(REGISTERED_ROBOTS)}))
"""


def test_a_shipped_name_written_over_before_its_spec_is_read_stays_written_over() -> None:
    assert _run(WRITTEN_OVER) == {"looked_up": "MyPanda", "listed": True}
