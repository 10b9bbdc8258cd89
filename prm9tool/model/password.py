"""The Expert access-level password, kept only as a salted PBKDF2 hash in QSettings.

Until a user changes it, the password is :data:`DEFAULT_PASSWORD` (documented in the help page
and the README, as PRM9.exe's default is documented for service staff). Removing the settings
key ``access/expert_password`` brings the default back: the password guards against accidental
expert edits, not against someone who can edit the settings (README, "Access levels").
Passwords are any Unicode text (``expért``, ``heslíčko``), compared in Unicode NFC form as
UTF-8 bytes. QtCore only.
"""

from __future__ import annotations

import hashlib
import hmac
import os
import unicodedata

from PySide6.QtCore import QSettings

DEFAULT_PASSWORD = "expert"
ITERATIONS = 200_000
# The iteration count is read from the settings: a hand-edited entry with fewer iterations
# (quicker to guess) or absurdly many (the check would freeze the window) matches no password.
MIN_ITERATIONS = 100_000
MAX_ITERATIONS = 10_000_000
_KEY = "access/expert_password"
MIN_LENGTH = 4


def _utf8(password: str) -> bytes:
    """The bytes a password is hashed and compared as (composed é and e + ◌́ are one)."""
    return unicodedata.normalize("NFC", password).encode("utf-8")


def _hash(password: str, salt: bytes, iterations: int) -> bytes:
    return hashlib.pbkdf2_hmac("sha256", _utf8(password), salt, iterations)


def encode_hash(password: str, iterations: int = ITERATIONS) -> str:
    """``pbkdf2_sha256$<iterations>$<salt hex>$<hash hex>`` for a new random salt."""
    salt = os.urandom(16)
    return f"pbkdf2_sha256${iterations}${salt.hex()}${_hash(password, salt, iterations).hex()}"


def matches(password: str, encoded: str) -> bool:
    """True if ``password`` produces ``encoded`` (constant-time comparison)."""
    try:
        scheme, iterations, salt, digest = encoded.split("$")
        count = int(iterations)
        if scheme != "pbkdf2_sha256" or not MIN_ITERATIONS <= count <= MAX_ITERATIONS:
            return False
        actual = _hash(password, bytes.fromhex(salt), count)
        expected = bytes.fromhex(digest)
    except ValueError:
        return False
    return hmac.compare_digest(actual, expected)


class PasswordStore:
    """Checks and changes the Expert password stored in ``settings``."""

    def __init__(self, settings: QSettings) -> None:
        self._settings = settings

    def _stored(self) -> str | None:
        value = self._settings.value(_KEY)
        return str(value) if value else None

    @property
    def is_default(self) -> bool:
        """True while the documented default password is still in use."""
        stored = self._stored()
        return stored is None or matches(DEFAULT_PASSWORD, stored)

    def check(self, password: str) -> bool:
        """True if ``password`` is the current Expert password."""
        stored = self._stored()
        if stored is None:
            return hmac.compare_digest(_utf8(password), _utf8(DEFAULT_PASSWORD))
        return matches(password, stored)

    def change(self, old: str, new: str) -> None:
        """Replace the password; raises ValueError with a user-facing reason."""
        if not self.check(old):
            raise ValueError("The current password is wrong.")
        if len(new) < MIN_LENGTH:
            raise ValueError(f"The new password must have at least {MIN_LENGTH} characters.")
        self._settings.setValue(_KEY, encode_hash(new))
        self._settings.sync()
