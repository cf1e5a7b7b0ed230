"""polymimic.Body: one value carrying a body's kind, primitive set, field and reach."""

import json
import pickle

import numpy as np
import pytest

import polymimic
from polymimic._native import EpisodeBatch
from polymimic.bodies import THESIS_BODIES, Field, WheeledBody, as_body, onto_field
from polymimic.learning import SegmentedDemonstrations

ROVER = WheeledBody("rover_value", length_mm=200, width_mm=180, wheel_base_mm=160, top_wheel_speed_mm_s=150,
                    field=Field(1500, 1000, 500, 60))


def test_built_in_bodies_know_their_field_primitives_and_reach():
    lego, tiny, humanoid = (polymimic.Body(n) for n in ("lego", "tiny", "humanoid"))
    assert (lego.kind, lego.name, lego.primitive_set) == ("lego", "lego", "wheeled")
    assert lego.field == Field(1020.0, 810.0, 405.0, 100.0)
    assert tiny.field == Field(560.0, 345.0, 172.5, 25.0)
    assert humanoid.primitives == ["forward", "backward", "left", "right", "stop", "sidestep_left", "sidestep_right",
                                   "kick"]
    # A wheeled body's reach is its half length and the ball's radius: (140 + 100) / 2, (15 + 25) / 2.
    assert (lego.reach_mm, lego.imitating_reach_mm, tiny.reach_mm) == (120.0, 120.0, 20.0)
    assert (humanoid.reach_mm, humanoid.imitating_reach_mm) == (160.0, 85.0)


def test_a_thesis_description_is_that_body_and_a_borrowed_name_is_refused():
    assert polymimic.Body(THESIS_BODIES["lego"]) == polymimic.Body("lego")
    assert polymimic.Body(THESIS_BODIES["tiny"]).kind == "tiny"
    assert polymimic.Body("tiny").description == THESIS_BODIES["tiny"]
    assert polymimic.Body("humanoid").description is None
    constants, field = THESIS_BODIES["lego"]._native_body()

    class Impostor:  # the Lego's name on a longer body
        def _native_body(self) -> tuple[str, str]:
            return json.dumps({**json.loads(constants), "length_mm": 141.0}), field

    with pytest.raises(ValueError, match='body name "lego" is a built-in body\'s; give your body a name of its own'):
        polymimic.Body(Impostor())


def test_an_unknown_name_lists_the_known_ones_and_says_how_to_describe_one():
    with pytest.raises(ValueError, match=r'unknown body "robot": the built-in bodies are lego, tiny, humanoid; '
                                         r"describe a body of your own with polymimic.bodies.WheeledBody"):
        polymimic.Body("robot")
    with pytest.raises(ValueError, match=r"^imitator: unknown body \"robot\""):
        as_body("robot", what="imitator")
    with pytest.raises(TypeError, match="polymimic.bodies.WheeledBody, got 3"):
        polymimic.Body(3)


def test_a_body_of_ones_own_carries_its_field_and_reach_and_pickles_equal():
    rover = polymimic.Body(ROVER)
    assert (rover.kind, rover.name, rover.primitive_set) == ("wheeled", "rover_value", "wheeled")
    assert rover.field == Field(1500, 1000, 500, 60)
    assert rover.reach_mm == rover.imitating_reach_mm == (200 + 60) / 2
    assert rover.description is ROVER
    again = pickle.loads(pickle.dumps(rover))
    assert again == rover and hash(again) == hash(rover) and again.description == ROVER
    assert rover != polymimic.Body("lego") and {rover, again, polymimic.Body("lego")} == {rover, polymimic.Body("lego")}
    assert polymimic.Body(rover) == rover


def test_from_table_reads_a_bodies_table_and_names_a_bad_key():
    cart = polymimic.Body.from_table("cart_value", {"length_mm": 90, "width_mm": 80, "wheel_base_mm": 70,
                                                    "top_wheel_speed_mm_s": 60, "field": "small"})
    assert (cart.kind, cart.field.length_mm, cart.description.primitives_mm_s["forward"]) == ("wheeled", 560.0,
                                                                                             (24.0, 24.0))
    with pytest.raises(ValueError, match=r"\[bodies.cart_bad\]: unknown key 'colour'"):
        polymimic.Body.from_table("cart_bad", {"length_mm": 90, "width_mm": 80, "wheel_base_mm": 70,
                                               "top_wheel_speed_mm_s": 60, "colour": "red"})


def test_onto_field_takes_bodies_and_maps_as_by_name():
    seen = np.array([[260.0, -86.25, 0.3, 280.0, -86.25]])  # the tiny touching the ball on the far post
    by_value = onto_field(seen, recorded_by=polymimic.Body("tiny"), imitator=polymimic.Body("lego"))
    assert by_value.tolist() == [[390.0, -202.5, 0.3, 510.0, -202.5]]
    assert onto_field(seen, recorded_by="tiny").tolist() == by_value.tolist()


def test_a_segmented_demonstration_given_its_body_has_that_bodys_field_and_reach():
    segments = {"label": ["forward"], "first_frame": np.array([0]), "last_frame": np.array([9]),
                "start": np.zeros((1, 5)), "end": np.zeros((1, 5))}
    by_body = SegmentedDemonstrations([
        {"demonstrator": "tiny", "outcome": "goal", "segments": segments, "body": polymimic.Body("tiny")},
        {"demonstrator": "imitator", "outcome": "goal", "segments": segments, "body": polymimic.Body("humanoid"),
         "imitating": True}])
    by_pitch = SegmentedDemonstrations([
        {"demonstrator": "tiny", "outcome": "goal", "segments": segments, "pitch": "small", "reach_mm": 20.0},
        {"demonstrator": "imitator", "outcome": "goal", "segments": segments, "pitch": "large", "reach_mm": 85.0}])
    assert by_body.pitches == by_pitch.pitches == ["small", "large"]
    assert [d["reach_mm"] for d in by_body] == [d["reach_mm"] for d in by_pitch] == [20.0, 85.0]
    with pytest.raises(TypeError, match="demonstration 0: imitating must be True or False, got 'yes'"):
        SegmentedDemonstrations([{"demonstrator": "tiny", "outcome": "goal", "segments": segments,
                                  "body": polymimic.Body("tiny"), "imitating": "yes"}])


def test_a_native_body_of_ones_own_hands_back_its_description():
    batch = EpisodeBatch(1, body=ROVER)  # the vector environment's engine
    assert batch.body == polymimic.Body(ROVER) and batch.body.name == "rover_value"
    # Made again from the constants the field holds: the same body, its slip given per primitive.
    assert polymimic.Body(batch.body.description) == polymimic.Body(ROVER)
    assert batch.body.description.slip_of("left") == ROVER.slip_of("left")
