"""A throw-away PostgreSQL cluster for the tests (the commands of docs/history.md).

``initdb`` and ``pg_ctl`` come from ``/usr/lib/postgresql/*/bin`` (Debian's postgresql
package; ``.ci/run`` installs it) or the PATH. PostgreSQL refuses to run as root, so as root
the cluster runs as the unprivileged user ``nobody``. It listens on 127.0.0.1 at a free port
and on a socket in its own folder, trusts local connections and is removed afterwards.
"""

from __future__ import annotations

import contextlib
import glob
import os
import pwd
import shutil
import socket
import subprocess
import tempfile
from collections.abc import Iterator
from pathlib import Path


class NoPostgresError(Exception):
    """No PostgreSQL server can be started here (the reason is the message)."""


def _bin_dir() -> Path:
    found = sorted(
        glob.glob("/usr/lib/postgresql/*/bin/initdb"),
        key=lambda p: int(p.split("/")[4]) if p.split("/")[4].isdigit() else 0,
    )
    if found:
        return Path(found[-1]).parent
    initdb = shutil.which("initdb")
    if initdb:
        return Path(initdb).parent
    raise NoPostgresError("no initdb: install PostgreSQL (apt-get install postgresql)")


def _free_port() -> int:
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return int(probe.getsockname()[1])


@contextlib.contextmanager
def cluster() -> Iterator[str]:
    """Start a cluster; yields its SQLAlchemy URL (database ``postgres``, user ``prm9tool``)."""
    tools = _bin_dir()
    folder = Path(tempfile.mkdtemp(prefix="prm9tool-pg-"))
    runner: list[str] = []
    if os.geteuid() == 0:
        nobody = pwd.getpwnam("nobody")
        os.chown(folder, nobody.pw_uid, nobody.pw_gid)
        runner = ["runuser", "-u", "nobody", "--"]
    data, port = folder / "data", _free_port()
    try:
        _run([*runner, str(tools / "initdb"), "-D", str(data), "-U", "prm9tool", "--auth=trust",
              "-E", "UTF8", "--no-sync"])  # fmt: skip
        options = f"-p {port} -k {folder} -c listen_addresses=127.0.0.1 -c fsync=off"
        _run([*runner, str(tools / "pg_ctl"), "-D", str(data), "-o", options, "-w",
              "-l", str(folder / "log"), "start"])  # fmt: skip
    except NoPostgresError:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    try:
        yield f"postgresql+psycopg://prm9tool@127.0.0.1:{port}/postgres"
    finally:
        subprocess.run([*runner, str(tools / "pg_ctl"), "-D", str(data), "-m", "immediate",
                        "stop"], capture_output=True, check=False)  # fmt: skip
        shutil.rmtree(folder, ignore_errors=True)


def _run(command: list[str]) -> None:
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=60, check=False)
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise NoPostgresError(f"{command[0]}: {exc}") from exc
    if done.returncode != 0:
        raise NoPostgresError(f"{' '.join(command)} failed: {done.stderr.strip()[-400:]}")


def new_database(url: str, name: str) -> str:
    """Create database ``name`` on the cluster; its URL."""
    import psycopg

    with psycopg.connect(url.replace("postgresql+psycopg", "postgresql"), autocommit=True) as conn:
        conn.execute(f'CREATE DATABASE "{name}"')
    return url.rsplit("/", 1)[0] + f"/{name}"
