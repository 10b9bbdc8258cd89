"""Issue 34 item 18: the tuning help page (~15 lines) did not say what to set for an E04
process loop, that accepting gains needs Expert, the acceptance profile's format with an
example, or how to leave FAULT_HOLD. Its example profile is read by the program itself."""

from __future__ import annotations

import html
import re
import tomllib

import pytest

from prm9tool.analysis.profile import parse_profile
from prm9tool.views.help_dialog import help_file

TOPICS = {  # language: what the page must say
    "en": ("Process controller (E04)", "Expert", "[process.limits]", "FAULT_HOLD", "08h"),
    "de": ("Prozessregler (E04)", "Experte", "[process.limits]", "FAULT_HOLD", "08h"),
    "cs": ("Procesní regulátor (E04)", "Expert", "[process.limits]", "FAULT_HOLD", "08h"),
}


def _page(path: str) -> str:
    from PySide6.QtCore import QFile

    file = QFile(path)
    assert file.open(QFile.OpenModeFlag.ReadOnly), path
    return bytes(file.readAll().data()).decode("utf-8")


@pytest.mark.parametrize("language", ["en", "de", "cs"])
def test_the_tuning_help_covers_the_process_loop_access_profile_and_faults(language):
    page = _page(help_file(language, "tuning"))
    for words in TOPICS[language]:
        assert words in page, words
    assert len(page.splitlines()) > 60  # was ~15 lines of text
    example = html.unescape(re.search(r"<pre>(.*?)</pre>", page, re.S).group(1))
    profile = parse_profile(tomllib.loads(example), "example")
    assert profile.limits["step_rise_s"].maximum == 0.03
    process = profile.for_loop("process")
    assert process.step_duration_s == 2.0 and process.limits["step_rise_s"].maximum == 0.5
