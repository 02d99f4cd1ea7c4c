"""The registry: metaclass registration, decorator, duplicates and unknown names."""

from __future__ import annotations

from pathlib import Path

import pytest

import assembler
from assembler.errors import RegistryError
from assembler.models import ManipulatorModel, RobotModel
from assembler.registry.lookup import REGISTERED_ROBOTS


def test_shipped_specs_are_registered_on_import() -> None:
    assert {"Sparrow7", "Finch6"} <= set(REGISTERED_ROBOTS)
    assert issubclass(REGISTERED_ROBOTS["Sparrow7"], ManipulatorModel)


def test_abstract_morphology_classes_are_never_registered() -> None:
    assert "RobotModel" not in REGISTERED_ROBOTS
    assert "ManipulatorModel" not in REGISTERED_ROBOTS


def test_a_spec_becomes_a_real_registered_class(two_link: Path) -> None:
    (cls,) = assembler.register_specs(two_link)
    assert cls.__name__ == "TwoLink" and REGISTERED_ROBOTS["TwoLink"] is cls
    assert isinstance(assembler.create_robot("TwoLink", idn=2), cls)


def test_python_subclasses_register_themselves(two_link: Path) -> None:
    (cls,) = assembler.register_specs(two_link)

    class TwoLinkStiff(cls):  # type: ignore[misc, valid-type]
        """A hand-written variant: subclassing a spec-made class is ordinary Python."""

    assert REGISTERED_ROBOTS["TwoLinkStiff"] is TwoLinkStiff
    assert assembler.create_robot("TwoLinkStiff").dof == 2


def test_abstract_subclasses_opt_out_and_their_children_do_not(two_link: Path) -> None:
    (cls,) = assembler.register_specs(two_link)

    class Family(cls):  # type: ignore[misc, valid-type]
        in_registry = False

    class Member(Family):
        pass

    assert "Family" not in REGISTERED_ROBOTS and "Member" in REGISTERED_ROBOTS


def test_register_robot_is_a_decorator(two_link: Path) -> None:
    (cls,) = assembler.register_specs(two_link)
    created = type("Plain", (object,), {})
    assert assembler.register_robot(created) is created  # type: ignore[arg-type]
    assert REGISTERED_ROBOTS["Plain"] is created


def test_duplicate_name_names_both_sources(two_link: Path, write, monkeypatch: pytest.MonkeyPatch) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.setenv(
        "ASSEMBLER_ALLOW_PATHS", str(two_link.parent.parent)
    )  # the MJCF sits in a sibling folder
    assembler.register_specs(two_link)
    other = write("elsewhere/twolink.yaml", "name: TwoLink\nmjcf: ../robots/twolink.xml\n")
    with pytest.raises(RegistryError) as caught:
        assembler.register_specs(other)
    message = str(caught.value)
    assert "elsewhere/twolink.yaml:1:7: name: robot 'TwoLink' is already registered by" in message
    assert "robots/twolink.yaml:1:1, a different spec; rename one" in message


def test_duplicate_python_class_names_both_sources(two_link: Path) -> None:
    assembler.register_specs(two_link)
    with pytest.raises(
        RegistryError,
        match=r"robot 'TwoLink' is defined twice: by .*twolink.yaml:1:1 and by tests.test_registry",
    ):
        type("TwoLink", (RobotModel,), {"__module__": "tests.test_registry"})


def test_registering_the_same_file_again_is_harmless(two_link: Path) -> None:
    assembler.register_specs(two_link)
    assembler.register_specs(two_link)
    assert assembler.create_robot("TwoLink").dof == 2


def test_unknown_name_lists_registered_names_and_the_closest() -> None:
    with pytest.raises(
        RegistryError,
        match=r"^unknown robot 'Sparow7'. Did you mean 'Sparrow7'\?$",
    ):
        assembler.create_robot("Sparow7").check()


def test_specs_can_extend_shipped_robots(write) -> None:  # type: ignore[no-untyped-def]
    (cls,) = assembler.register_specs(
        write(
            "mine/soft.yaml",
            "name: SoftSparrow\nextends: Sparrow7\njoint_defaults: {damping: 0.5}\n",
        )
    )
    robot = cls(idn=0)
    assert robot.dof == 7
    assert robot.joint_values["joint1"]["damping"].value == 0.5
