"""A summary quantity that is ±∞ says it is infinite, as json_ready does, and a NaN that it is
not defined; a reason the caller gives wins."""

import json
import math

import numpy as np

from ballscrew.analyses.result import INFINITE, UNDEFINED, json_ready, quantity


def test_an_infinite_quantity_says_infinite_and_agrees_with_json_ready():
    for number in (math.inf, -math.inf, np.float64(np.inf), math.nan):
        direct = quantity(number, "K/W")
        walked = json_ready({"value": number, "unit": "K/W"})
        assert direct == walked
        json.dumps(direct, allow_nan=False)
    assert quantity(math.inf, "K/W")["reason"] == INFINITE[True] == "infinite (+∞): no limit"
    assert quantity(-math.inf, "K/W")["reason"] == INFINITE[False]
    assert quantity(math.nan, "K/W")["reason"] == UNDEFINED
    assert quantity(math.inf, "s", "not reached")["reason"] == "not reached"
    assert quantity(2.0, "s", "not reached") == {"value": 2.0, "unit": "s"}
