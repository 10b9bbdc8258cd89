"""The Expert password: any Unicode text, a bounded iteration count, and what removing the
settings key does (issue 15, items 18 and 19)."""

from __future__ import annotations

import hashlib
import unicodedata

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QDialog

from prm9tool.model import password as pw
from prm9tool.model.password import DEFAULT_PASSWORD, PasswordStore
from prm9tool.views.access_dialog import ChangePasswordDialog, PasswordDialog

NON_ASCII = ["expért", "heslíčko", "Passwört", "пароль"]


@pytest.fixture
def settings(tmp_path):
    return QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)


@pytest.fixture
def store(settings):
    return PasswordStore(settings)


@pytest.mark.parametrize("guess", NON_ASCII)
def test_a_non_ascii_guess_against_the_default_password_is_just_wrong(store, guess):
    assert store.check(guess) is False
    assert store.check(DEFAULT_PASSWORD) is True


@pytest.mark.parametrize("guess", NON_ASCII)
def test_the_dialog_says_wrong_password_for_a_non_ascii_guess(qtbot, store, guess):
    dialog = PasswordDialog(store)
    qtbot.addWidget(dialog)
    dialog.password.setText(guess)
    dialog._on_accepted()  # raised TypeError from hmac.compare_digest on a str
    assert dialog.error_label.text() == "Wrong password."
    assert dialog.result() != QDialog.DialogCode.Accepted


@pytest.mark.parametrize("new", NON_ASCII)
def test_a_non_ascii_password_can_be_set_and_is_then_the_password(qtbot, store, settings, new):
    dialog = ChangePasswordDialog(store)
    qtbot.addWidget(dialog)
    dialog.old.setText("heslo-é")
    dialog._on_accepted()
    assert dialog.error_label.text() == "The current password is wrong."
    dialog.old.setText(DEFAULT_PASSWORD)
    dialog.new.setText(new)
    dialog.repeat.setText(new)
    dialog._on_accepted()
    assert dialog.result() == QDialog.DialogCode.Accepted
    fresh = PasswordStore(settings)
    assert fresh.check(new) and not fresh.check(DEFAULT_PASSWORD) and not fresh.is_default
    # typed with a combining accent (another keyboard layout): the same password
    assert fresh.check(unicodedata.normalize("NFD", new))


def _entry(password: str, iterations: int) -> str:
    salt = b"0123456789abcdef"
    digest = hashlib.pbkdf2_hmac("sha256", password.encode(), salt, iterations)
    return f"pbkdf2_sha256${iterations}${salt.hex()}${digest.hex()}"


@pytest.mark.parametrize("iterations", [1, 1000, pw.MIN_ITERATIONS - 1])
def test_a_stored_hash_with_too_few_iterations_matches_no_password(store, settings, iterations):
    settings.setValue("access/expert_password", _entry("valve-42", iterations))
    assert store.check("valve-42") is False
    assert store.check(DEFAULT_PASSWORD) is False


def test_a_stored_hash_with_absurdly_many_iterations_is_refused_without_computing_it(
    store, settings
):
    settings.setValue("access/expert_password", f"pbkdf2_sha256${10**12}$00$00")
    assert store.check("valve-42") is False  # PBKDF2 with 10^12 rounds would take a day


def test_a_stored_hash_within_the_bounds_is_the_password(store, settings):
    settings.setValue("access/expert_password", _entry("valve-42", pw.MIN_ITERATIONS))
    assert store.check("valve-42") and not store.check("valve-43")


@pytest.mark.parametrize("damaged", ["pbkdf2_sha256$x$00$00", "md5$1$2$3", "é$é$é$é", "zz"])
def test_a_damaged_entry_matches_no_password_and_raises_nothing(qtbot, store, settings, damaged):
    settings.setValue("access/expert_password", damaged)
    dialog = PasswordDialog(store)
    qtbot.addWidget(dialog)
    for guess in [DEFAULT_PASSWORD, *NON_ASCII]:
        dialog.password.setText(guess)
        dialog._on_accepted()
        assert dialog.error_label.text() == "Wrong password."


def test_removing_the_settings_key_brings_back_the_default_password(store, settings):
    store.change(DEFAULT_PASSWORD, "heslíčko")
    assert not store.check(DEFAULT_PASSWORD)
    settings.remove("access/expert_password")  # documented in the README: "Access levels"
    assert store.check(DEFAULT_PASSWORD) and store.is_default


def test_the_password_dialog_says_where_the_delivered_password_is_written(qtbot, store):
    """Issue 34, item 15: the dialog gave no hint; the manual says only that the Expert level
    is password-protected (§8.5), the help page says what it is as delivered."""
    from prm9tool.views import help_dialog

    dialog = PasswordDialog(store)
    qtbot.addWidget(dialog)
    assert "The password as delivered is written in the help" in dialog.hint.text()
    dialog.hint.linkActivated.emit("help")
    window = help_dialog.help_window(dialog)
    qtbot.addWidget(window)
    assert window.isVisible() and window.topic == "help"
    assert f"The password as delivered is {DEFAULT_PASSWORD}" in window.browser.toPlainText()
