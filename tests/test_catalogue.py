"""The parameter catalogue is consistent: unique names and addresses, sane defaults, texts."""

from __future__ import annotations

import pytest

from prm9tool.catalogue import CATALOGUE, Access, ObjAccess
from prm9tool.catalogue.variant import ALL_VARIANTS, Coils, Config, Variant

BASIC_LIST = [
    "AINSETP",
    "INVERSEP",
    "THRESETP",
    "RAMPSETPOSUP",
    "RAMPSETPOSDOWN",
    "RAMPSETNEGUP",
    "RAMPSETNEGDOWN",
    "GAINSETPOS",
    "GAINSETNEG",
    "OFFSETPOS",
    "OFFSETNEG",
    "LIMTA",
    "LIMTB",
    "DYNFREQ",
    "DTAMP",
]


def test_mnemonics_and_addresses_are_unique():
    mnemonics = [p.mnemonic for p in CATALOGUE]
    keys = [p.key for p in CATALOGUE]
    assert len(set(mnemonics)) == len(mnemonics)
    assert len(set(keys)) == len(keys)


@pytest.mark.parametrize("variant", ALL_VARIANTS, ids=lambda v: v.label)
def test_defaults_lie_within_ranges(variant):
    for p in CATALOGUE.for_variant(variant):
        if not p.is_string and p.obj_access is not ObjAccess.WO:
            p.check_raw(p.default_for(variant, node_id=10))  # node 10: delivery state


def test_every_parameter_has_three_languages():
    for p in CATALOGUE:
        assert p.text.en and p.text.de and p.text.cs, p.mnemonic
        for _, label in p.choices:
            assert label.en and label.de and label.cs


def test_basic_list_of_figure_8_18_is_basic_with_the_manual_defaults():
    two_coils = Variant(Config.E02, Coils.AB)
    visible = {p.mnemonic for p in CATALOGUE.visible(two_coils, Access.BASIC)}
    assert set(BASIC_LIST) <= visible
    defaults = CATALOGUE.defaults(two_coils)
    shown = {mn: CATALOGUE[mn].format_display(defaults[mn]) for mn in BASIC_LIST}
    assert shown["AINSETP"] == "9"
    assert shown["THRESETP"] == "5"
    assert shown["LIMTA"] == shown["LIMTB"] == "2400"
    assert shown["DYNFREQ"] == "80"
    assert shown["DTAMP"] == "15"
    assert shown["GAINSETPOS"] == "1"


def test_basic_level_hides_controllers_and_linearizations():
    e04 = Variant(Config.E04, Coils.AB, True)
    basic = {p.mnemonic for p in CATALOGUE.visible(e04, Access.BASIC)}
    expert = {p.mnemonic for p in CATALOGUE.visible(e04, Access.EXPERT)}
    for hidden in ("POSKP", "PRCKI", "SETPLINXA", "SENSLINYI", "SENSGAIN"):
        assert hidden not in basic
        assert hidden in expert


def test_variant_filtering():
    coil_a = Variant(Config.E02, Coils.A)
    names = {p.mnemonic for p in CATALOGUE.for_variant(coil_a)}
    assert "LIMTA" in names and "LIMTB" not in names
    assert "PRCKP" not in names and "HEARTBEAT" not in names
    e04_ca = Variant(Config.E04, Coils.B, True)
    names = {p.mnemonic for p in CATALOGUE.for_variant(e04_ca)}
    assert {"LIMTB", "PRCKP", "SENSTYPE", "HEARTBEAT", "NODEID"} <= names
    assert "LIMTA" not in names


def test_the_sensor_objects_are_on_every_ca_valve_but_parameters_of_the_e04_only():
    """Table 7-14: 0x2005-0x2008 and 0x2100 are objects of all valves; the E02 has no sensor
    input (table 7-22), so they are not part of its parameter set."""
    sensor = {
        p.mnemonic for p in CATALOGUE if p.index in range(0x2005, 0x2009) or p.index == 0x2100
    }
    assert len(sensor) == 29
    for config, coils, canopen, objects, parameters in (
        (Config.E02, Coils.AB, True, True, False),
        (Config.E02, Coils.A, True, True, False),
        (Config.E02, Coils.AB, False, False, False),
        (Config.E04, Coils.B, True, True, True),
        (Config.E04, Coils.AB, False, True, True),
    ):
        variant = Variant(config, coils, canopen)
        on_device = {p.mnemonic for p in CATALOGUE.for_variant(variant)}
        in_set = {p.mnemonic for p in CATALOGUE.parameter_set(variant)}
        in_file = {p.mnemonic for p in CATALOGUE.file_parameters(variant)}
        shown = {p.mnemonic for p in CATALOGUE.visible(variant, Access.EXPERT)}
        assert (sensor <= on_device) is objects and bool(sensor & on_device) is objects
        assert (sensor <= in_set) is parameters and bool(sensor & in_set) is parameters
        assert bool(sensor & (in_file | shown)) is parameters
        assert in_set <= on_device
    e02_ca = Variant(Config.E02, Coils.AB, True)
    assert CATALOGUE["TPDO2MAPN"].default_for(e02_ca) == 2  # table 7-13 on every -CA valve
    assert CATALOGUE["RPDO2MAPN"].default_for(e02_ca) == 1
    assert CATALOGUE["SENSTYPE"].applies.describe() == "E04, object also on E02 -CA"


def _subs(index: int, *subs: int) -> list[tuple[int, int]]:
    return [(index, sub) for sub in subs]


# Every entry of manual tables 7-13, 7-14 and 7-16 (the "number of entries" subindex 0 of the
# arrays 0x2000…0x2007 and of the CiA 408 records is the object dictionary's, not a parameter).
TABLE_7_13 = [
    *[(i, 0) for i in (0x1000, 0x1001, 0x1003, 0x1005, 0x1006, 0x1008, 0x1009, 0x100A)],
    *[(i, 0) for i in (0x1014, 0x1017, 0x1F80)],
    *_subs(0x1018, 0, 1, 2, 3, 4),
    *_subs(0x1400, 0, 1, 2),
    *_subs(0x1401, 0, 1, 2),
    *_subs(0x1600, 0, 1, 2),
    *_subs(0x1601, 0, 1),
    *_subs(0x1800, 0, 1, 2, 5),
    *_subs(0x1801, 0, 1, 2, 5),
    *_subs(0x1A00, 0, 1, 2),
    *_subs(0x1A01, 0, 1, 2),
]
TABLE_7_14 = [
    *[(i, sub) for i in (0x2000, 0x2001, 0x2006, 0x2007) for sub in range(1, 10)],
    (0x2002, 0),
    (0x2003, 0),
    *_subs(0x2004, 1, 2, 3),
    *_subs(0x2005, 1, 2, 3, 4),
    (0x2008, 0),
    *_subs(0x2100, 1, 2, 3, 4, 5, 6),
]
TABLE_7_16 = [
    *[(i, 0) for i in (0x6040, 0x6041, 0x6042, 0x6043, 0x605F, 0x6330, 0x6340, 0x6341)],
    *[(i, 0) for i in (0x6342, 0x6346, 0x6351, 0x6360)],
    *[(i, 1) for i in (0x6300, 0x6301, 0x6310, 0x6332, 0x6333, 0x6335, 0x6336, 0x6343)],
    *[(i, 1) for i in (0x6344, 0x6345, 0x6350, 0x6352, 0x6353, 0x6361, 0x6362, 0x6380)],
    (0x6381, 1),
]


@pytest.mark.parametrize(
    ("index", "sub"),
    TABLE_7_13 + TABLE_7_14 + TABLE_7_16,
    ids=lambda v: f"{v:X}" if v > 9 else str(v),
)
def test_every_object_of_tables_7_13_7_14_7_16_is_in_the_catalogue(index, sub):
    assert CATALOGUE.by_address(index, sub) is not None


@pytest.mark.parametrize("variant", ALL_VARIANTS, ids=lambda v: v.label)
def test_factory_defaults_break_no_rule_and_raise_no_warning(variant):
    assert CATALOGUE.check_rules(variant, CATALOGUE.defaults(variant, node_id=10)) == []


def test_display_text_round_trips_every_raw_value_of_scaled_parameters():
    for mn in ("THRESETP", "DTAMP", "GAINSETPOS", "SENSGAIN", "POSKP", "PWR"):
        p = CATALOGUE[mn]
        for raw in range(p.raw_min, p.raw_max + 1, max(1, (p.raw_max - p.raw_min) // 997)):
            assert p.parse_display(p.format_display(raw)) == raw


def test_out_of_range_message_names_limits_and_unit():
    with pytest.raises(Exception, match=r"LIMTA: 4200 mA is outside the allowed range 0 … 4000 mA"):
        CATALOGUE["LIMTA"].check_raw(4200)


def test_cross_rules():
    variant = Variant(Config.E02, Coils.AB)
    values = CATALOGUE.defaults(variant)
    assert CATALOGUE.check_rules(variant, values) == []
    values["LIMTA"] = 3000
    values["SETPLINYC"] = -16384
    values["AINSETP"] = 6
    problems = CATALOGUE.check_rules(variant, values)
    messages = " | ".join(p.message for p in problems)
    assert "LIMTA = 3000 mA is above the nominal coil current CURNORM = 2600 mA" in messages
    assert "SETPLIN linearization outputs must not decrease: SETPLINYC < SETPLINYB" in messages
    assert any(p.severity == "warning" and "table 8-4" in p.message for p in problems)


def test_linearization_outputs_may_stay_level_but_not_fall():
    variant = Variant(Config.E02, Coils.AB)
    values = CATALOGUE.defaults(variant)
    values["SETPLINYC"] = values["SETPLINYB"]  # level: allowed (a dead band)
    assert CATALOGUE.check_rules(variant, values) == []
    values["SETPLINXC"] = values["SETPLINXB"]  # X points must differ
    assert [p.message for p in CATALOGUE.check_rules(variant, values)] == [
        "SETPLIN: SETPLINXC equals SETPLINXB; X points must differ"
    ]


def test_factory_setpoint_type_follows_the_coil_layout():
    # Table 7-22: ±10 V bipolar on delivery; table 8-4 recommends unipolar types for one coil.
    ainsetp = CATALOGUE["AINSETP"]
    assert ainsetp.default_for(Variant(Config.E02, Coils.AB)) == 9
    for coils in (Coils.A, Coils.B):
        variant = Variant(Config.E04, coils)
        assert ainsetp.default_for(variant) == 6
        assert CATALOGUE.check_rules(variant, CATALOGUE.defaults(variant)) == []
