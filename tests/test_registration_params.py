"""Declared parameters: validation messages, generated invalid-value checks for every method, registry."""

from __future__ import annotations

import numpy as np
import pytest

from coindie.errors import ParameterError
from coindie.registration import (
    PointToPlaneICP,
    TeaserSolver,
    get_method,
    list_methods,
    method_info,
    register_method,
)
from test_params import outside_values


def test_the_message_names_the_parameter_the_part_the_range_and_the_value() -> None:
    with pytest.raises(ParameterError) as error:
        TeaserSolver(noise_bound=-1)
    assert (
        str(error.value)
        == "The 'noise_bound' parameter of teaser must be a float in the range (0, inf) mm. Got -1."
    )


def test_choices_and_kinds_in_messages() -> None:
    with pytest.raises(
        ParameterError, match=r"'init' parameter of icp must be one of 'identity', 'centroids'\. Got 'x'"
    ):
        PointToPlaneICP(init="x")
    with pytest.raises(ParameterError, match=r"must be an int in the range \[1, inf\)\. Got 2\.5"):
        PointToPlaneICP(max_iterations=2.5)
    with pytest.raises(ParameterError, match="Got True"):
        PointToPlaneICP(max_iterations=True)  # a bool is not a count
    assert PointToPlaneICP(max_iterations=3.0).max_iterations == 3  # an integral float is accepted as an int
    assert PointToPlaneICP(max_iterations=np.int64(7)).max_iterations == 7  # and NumPy scalars
    assert TeaserSolver(noise_bound=np.float32(0.25)).noise_bound == 0.25
    with pytest.raises(ParameterError, match="Got inf"):
        PointToPlaneICP(max_iterations=float("inf"))
    assert isinstance(TeaserSolver(noise_bound=1).noise_bound, float)


CASES = [
    (method, key, value)
    for method in list_methods()
    for key, p in method_info(method).params().items()
    for value in outside_values(p)
]


@pytest.mark.parametrize(("method", "key", "value"), CASES, ids=[f"{m}-{k}-{v!r}" for m, k, v in CASES])
def test_every_declared_parameter_refuses_values_outside_its_declaration(
    method: str, key: str, value
) -> None:
    part, name = key.split(".")
    with pytest.raises(ParameterError, match=rf"The '{name}' parameter of {part} must be .* Got "):
        get_method(method, **{key: value})


@pytest.mark.parametrize("method", list_methods())
def test_defaults_are_valid_and_recorded_in_full(method: str) -> None:
    info = method_info(method)
    registrar = get_method(method)
    assert registrar.params == {key: p.default for key, p in info.params().items()}
    assert registrar.name == method
    assert info.summary


def test_short_names_resolve_when_unique_and_are_refused_when_ambiguous() -> None:
    registrar = get_method("fpfh+teaser+icp", noise_bound=0.3, **{"refine.max_iterations": 5})
    assert registrar.params["teaser.noise_bound"] == 0.3
    assert registrar.params["refine.max_iterations"] == 5
    with pytest.raises(
        ParameterError, match="ambiguous: say one of teaser.max_iterations, refine.max_iterations"
    ):
        get_method("fpfh+teaser+icp", max_iterations=5)
    with pytest.raises(
        ParameterError, match="Method 'icp' has no parameter 'noise_bound'. Its parameters: icp.max"
    ):
        get_method("icp", noise_bound=0.3)


def test_unknown_method_lists_the_known_ones() -> None:
    with pytest.raises(
        ParameterError, match="Unknown registration method 'teaser'. Known methods: icp, rs-icp"
    ):
        get_method("teaser")


def test_command_line_text_is_parsed_by_the_declaration() -> None:
    info = method_info("fpfh+ransac+icp")
    assert info.parse("distance", "0.25") == ("ransac.distance", 0.25)
    assert info.parse("n_points", "250") == ("matcher.n_points", 250)
    assert info.parse("check.max_residual", "1e-2") == ("check.max_residual", 0.01)
    with pytest.raises(
        ParameterError, match="The 'n_points' parameter of matcher must be an int .* Got 'many'"
    ):
        info.parse("n_points", "many")
    assert method_info("icp").parse("init", "centroids") == ("icp.init", "centroids")


def test_parts_of_a_method_need_distinct_names() -> None:
    with pytest.raises(ValueError, match="distinct names"):
        register_method("twice", lambda **parts: None, parts=(TeaserSolver, TeaserSolver), summary="x")
    assert "twice" not in list_methods()


def test_every_method_lists_its_acceptance_check() -> None:
    for method in list_methods():
        params = method_info(method).params()
        assert {"check.overlap_distance", "check.min_fitness", "check.max_residual"} <= set(params)
        assert all(p.doc for p in params.values())


def test_relief_for_larger_or_smaller_coins_scales_the_lengths_of_the_design_alone() -> None:
    """The lengths set by the size of a die's details follow the coins; the scanner's (the ICP's reach) and
    those the user gave do not."""
    from coindie.registration import method_info

    info = method_info("relief")
    defaults = {key: p.default for key, p in info.params().items()}
    assert info.for_coins({"icp.max_distance": 0.2}, 1.0) == {"icp.max_distance": 0.2}

    half = info.for_coins({"margin": 0.3}, 0.5)  # a short name, resolved

    assert half["blocks.window"] == defaults["blocks.window"] / 2
    assert half["relief.field_size"] == defaults["relief.field_size"] / 2
    assert half["relief.pixel"] == defaults["relief.pixel"] / 2
    assert half["margin"] == 0.3 and "relief.margin" not in half  # the one given is left to the user
    assert "icp.max_distance" not in half and "icp.final_distance" not in half
    info.build(half)  # every scaled value within its parameter's range
    assert method_info("fcgf+icp").for_coins({}, 0.5) == {}  # no length of a design declared
