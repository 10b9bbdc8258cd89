"""``--fit-twin OUT.toml --from RUN.json``: a valve's twin from a characterization's report
(docs/twin.md). The fit of a valve it moves itself (``--device``/``--emulator``) is not here
yet."""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from prm9tool.errors import ExitCode, Prm9Error


def run(args: argparse.Namespace) -> int:
    """Fit, write the twin file, print the fit report (``--json``: as JSON)."""
    from prm9tool.twin.identify import fit, from_report
    from prm9tool.twin.twinfile import write_twin

    try:
        report = json.loads(Path(args.fit_from).read_text(encoding="utf-8"))
        recordings = from_report(args.fit_from)
        result = fit(recordings)
        valve = report["valve"]
        write_twin(
            args.fit_twin,
            result,
            int(valve.get("serial") or 0),
            str(valve["type_key"]),
            str(valve.get("firmware") or ""),
            f"{len(recordings)} position-loop steps of {args.fit_from} ({report.get('date', '')})",
            recordings[0].values,
        )
    except OSError as exc:
        print(f"prm9tool: cannot read {args.fit_from}: {exc.strerror or exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    except (Prm9Error, KeyError, ValueError) as exc:
        print(f"prm9tool: --fit-twin: {exc}", file=sys.stderr)
        return ExitCode.INVALID_FILE
    rows = [
        {
            "constant": c.name,
            "start": c.start,
            "value": c.value,
            "relative_se": c.relative_se if c.relative_se != float("inf") else None,
            "determined": c.determined,
            "correlated_with": c.correlated_with,
        }
        for c in result.constants
    ]
    if args.json:
        summary = {
            "twin": str(args.fit_twin),
            "rms_pct": result.rms_pct,
            "max_pct": result.max_pct,
            "start_rms_pct": result.start_rms_pct,
            "explained": result.explained,
            "constants": rows,
        }
        text = json.dumps(summary, indent=2)
        if isinstance(args.json, str):  # --json OUT.json: the fit report into that file
            Path(args.json).write_text(text + "\n", encoding="utf-8")
        else:
            print(text)
        return ExitCode.OK
    print(f"twin {args.fit_twin}: residual {result.start_rms_pct:.3f} % → {result.rms_pct:.3f} %"
          f" rms ({'explained' if result.explained else 'NOT explained by the plant structure'})")  # fmt: skip
    for c in result.constants:
        state = "determined" if c.determined else "not determined, kept"
        print(f"  {c.name}: {c.start:g} → {c.value:.4g} ({state})")
    return ExitCode.OK
