"""Model-layer messages: English by str(), any language through a translate function (no Qt)."""

from __future__ import annotations

import pytest

from prm9tool.catalogue import CATALOGUE, Texts
from prm9tool.errors import ValueRangeError
from prm9tool.messages import QT_TRANSLATE_NOOP

ABOVE = QT_TRANSLATE_NOOP("Problems", "{0} = {1} mA is above {2}")
GERMAN = {
    ("Problems", "{0} = {1} mA is above {2}"): "{0} = {1} mA liegt über {2}",
    ("Problems", "the limit {0}"): "der Grenze {0}",
}


def _german(context: str, source: str) -> str:
    return GERMAN.get((context, source), source)


def test_str_is_the_english_sentence():
    assert str(ABOVE("LIMTA", 2650, "CURNORM")) == "LIMTA = 2650 mA is above CURNORM"
    assert str(ValueRangeError(ABOVE("LIMTA", 2650, "CURNORM"))).startswith("LIMTA = 2650")


def test_render_translates_the_template_and_the_arguments_that_are_texts():
    limit = QT_TRANSLATE_NOOP("Problems", "the limit {0}")(Texts("two coils", "zwei Spulen", "x"))
    message = ABOVE("LIMTA", 2650, limit)
    assert message.render(_german, "de") == "LIMTA = 2650 mA liegt über der Grenze zwei Spulen"
    assert str(message) == "LIMTA = 2650 mA is above the limit two coils"


def test_a_broken_translation_falls_back_to_english():
    def broken(_context: str, _source: str) -> str:
        return "{0} {7}"

    assert ABOVE("LIMTA", 1, "X").render(broken, "de") == "LIMTA = 1 mA is above X"


def test_catalogue_errors_carry_their_template():
    with pytest.raises(ValueRangeError) as caught:
        CATALOGUE["LIMTA"].check_raw(4200)
    (message,) = caught.value.args
    assert message.template.context == "Problems"
    assert message.template.source == "{0}: {1}{2} is outside the allowed range {3} … {4}{2}"
    assert str(caught.value) == "LIMTA: 4200 mA is outside the allowed range 0 … 4000 mA"
