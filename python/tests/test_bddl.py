"""The BDDL tools from Python: checking, evaluating a goal on a state, options; bad input
raises with where and why."""

import pytest

from behavior import bddl

BAD = """(define (problem broken) (:domain igibson)
  (:objects apple.n.01_1 - apple.n.01)
  (:init (ontop apple.n.01_1))
  (:goal (and)))
"""


def test_official_definitions_check_clean_and_a_broken_file_is_located(tmp_path):
    assert bddl.check("storing_food").ok
    path = tmp_path / "broken.bddl"
    path.write_text(BAD)
    report = bddl.check(path)
    assert not report.ok and report.errors == 1
    assert f"{path}:3:11: error: `ontop` takes 2 arguments, 1 given" in report.text


def test_a_goal_is_evaluated_on_the_facts_that_hold():
    none = bddl.evaluate("bringing_in_wood", [])
    assert (none["success"], none["q"], none["volume"]) == (False, 0.0, 3)
    two = bddl.evaluate("bringing_in_wood", [
        ("onfloor", f"plywood.n.01_{i}", "floor.n.01_2") for i in (1, 2)])
    assert two["q_exact"] == "2/3" and not two["success"]
    assert two["conjuncts"][0]["formula"].startswith("(forall (?plywood.n.01 - plywood.n.01)")
    every = bddl.evaluate("bringing_in_wood", [
        ("onfloor", f"plywood.n.01_{i}", "floor.n.01_2") for i in (1, 2, 3)])
    assert every["success"] and every["q"] == 1.0 and every["conjuncts"][0]["holds"]


def test_options_are_listed_smallest_first():
    volume, options = bddl.options("bringing_in_wood")
    assert volume == 3
    assert options == [[f"(onfloor plywood.n.01_{i} floor.n.01_2)" for i in (1, 2, 3)]]
    assert bddl.options("storing_food", limit=0)[1] == []


def test_bad_input_says_where_and_why():
    with pytest.raises(ValueError, match="`no_such` is neither a file nor an official activity"):
        bddl.check("no_such")
    with pytest.raises(ValueError, match=r"the state: fact 0 .*`ontop` takes 2 argument"):
        bddl.evaluate("bringing_in_wood", [("ontop", "plywood.n.01_1")])
    with pytest.raises(ValueError, match="limit must be at least 0"):
        bddl.options("storing_food", limit=-1)
