"""Registries of rival models: the table, the case's allowed names, and each family's entries."""

from __future__ import annotations

import pytest

import ballscrew
from ballscrew.case import CaseError
from ballscrew.case.base import Model, model_choice
from ballscrew.contact_resistance import ELEMENT_MODELS
from ballscrew.errors import InputError
from ballscrew.friction import BALL_TRAIN_MODELS, FRICTION_MODELS
from ballscrew.geometry import GAP_MODELS
from ballscrew.kinematics import TRACTION_LAWS
from ballscrew.loads import DRAG_TORQUE_MODELS, DragTorqueInputs, preload_drag_torque
from ballscrew.lubrication import FILM_MODELS, hamrock_dowson
from ballscrew.registry import Registry
from ballscrew.thermal import THERMAL_MODELS
from ballscrew.wear import WEAR_LAWS


def test_registry_is_an_ordered_name_to_model_table():
    table: Registry[int] = Registry("test model", "section.key")
    table.add("one", "the first", 1)

    @table.register("two", "the second")
    def two() -> int:
        return 2

    assert table.names == ("one", "two") and list(table) == ["one", "two"]
    assert table["one"] == 1 and table["two"] is two and len(table) == 2
    assert table.describe() == {"one": "the first", "two": "the second"}
    with pytest.raises(ValueError, match="registered twice"):
        table.add("one", "again", 3)
    with pytest.raises(InputError, match=r"^section.key = 'three' .*one of one, two$"):
        table["three"]


def test_a_case_field_accepts_exactly_the_registered_names():
    table: Registry[int] = Registry("test model", "section.key")
    table.add("a", "", 1)

    class Section(Model):
        model: model_choice(table, "which model") = "a"

    assert Section().model == "a"
    with pytest.raises(ValueError, match="is not allowed: it must be one of a"):
        Section(model="b")
    table.add("b", "a rival published later", 2)
    assert Section(model="b").model == "b"


@pytest.mark.parametrize(
    ("key", "registry"),
    [
        ("numerics.gap_model", GAP_MODELS),
        ("tcr.variant", ELEMENT_MODELS),
        ("thermal.model", THERMAL_MODELS),
        ("thermal.drag_torque.source", DRAG_TORQUE_MODELS),
        ("medium.film_model", FILM_MODELS),
        ("friction.model", FRICTION_MODELS),
        ("friction.traction", TRACTION_LAWS),
        ("friction.ball_train", BALL_TRAIN_MODELS),
    ],
)
def test_case_files_refuse_unknown_model_names_with_the_list(gao_case_path, key, registry):
    with pytest.raises(CaseError) as info:
        ballscrew.load_case(gao_case_path, {key: "nonsense"})
    message = str(info.value)
    assert f"{key} = 'nonsense' is not allowed: it must be one of" in message
    assert ", ".join(registry.names) in message


def test_wear_law_names_come_from_the_registry(wear_case_path):
    with pytest.raises(CaseError, match=r"wear\.model = 'B' is not allowed: .* one of A, C"):
        ballscrew.load_case(wear_case_path, {"wear.model": "B"})
    assert WEAR_LAWS.names == ("A", "C")


def test_drag_torque_models():
    inputs = DragTorqueInputs(1500.0, 0.01, 0.0794, given=0.3, ball_model=lambda: 0.12)
    assert DRAG_TORQUE_MODELS["catalogue"](inputs) == preload_drag_torque(1500.0, 0.01, 0.0794)
    assert DRAG_TORQUE_MODELS["given"](inputs) == 0.3
    assert DRAG_TORQUE_MODELS["kinematics"](inputs) == 0.12
    bare = DragTorqueInputs(1500.0, 0.01, 0.0794)
    with pytest.raises(InputError, match=r"thermal\.drag_torque\.torque"):
        DRAG_TORQUE_MODELS["given"](bare)


def test_film_models_hold_hamrock_dowson():
    assert FILM_MODELS["hamrock_dowson"] is hamrock_dowson
