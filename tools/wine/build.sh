#!/usr/bin/env bash
# Build the Wine stand-in DLLs (test scaffolding, never shipped: README.md beside this file).
#   tools/wine/build.sh OUTDIR [WINE_UCRTBASE]
# OUTDIR gets icuuc.dll, ucrtbase.dll (the proxy) and ucrtwine.dll (Wine's own ucrtbase, which
# the proxy forwards to). Needs Debian's gcc-mingw-w64-x86-64-win32.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=$1
wine_ucrt=${2:-/usr/lib/x86_64-linux-gnu/wine/x86_64-windows/ucrtbase.dll}
CC=x86_64-w64-mingw32-gcc
OBJDUMP=x86_64-w64-mingw32-objdump
mkdir -p "$out"
$CC -O2 -Wall -Wextra -shared -static-libgcc -o "$out/icuuc.dll" "$here/icuuc.c"
# the proxy's exports: ours (p_NAME as NAME), every other one forwarded to Wine's (ucrtwine)
cp "$wine_ucrt" "$out/ucrtwine.dll"
$CC -O2 -Wall -Wextra -c -o "$out/ucrtbase_complex.o" "$here/ucrtbase_complex.c"
x86_64-w64-mingw32-nm -g --defined-only "$out/ucrtbase_complex.o" | awk '$3 ~ /^p_/ {print substr($3, 3)}' \
  | sort -u > "$out/ours.txt"
$OBJDUMP -p "$wine_ucrt" | sed -n '/\[Ordinal\/Name Pointer\] Table/,/^$/p' \
  | sed -n 's/^\s*\[ *[0-9]*\] //p' | sort -u > "$out/wine_exports.txt"
{
  echo "LIBRARY ucrtbase.dll"
  echo "EXPORTS"
  sed 's/.*/&=p_&/' "$out/ours.txt"
  comm -23 "$out/wine_exports.txt" "$out/ours.txt" | sed 's/.*/&=ucrtwine.&/'
} > "$out/ucrtbase.def"
$CC -O2 -shared -static-libgcc -o "$out/ucrtbase.dll" "$out/ucrtbase.def" "$out/ucrtbase_complex.o" -lmingwex
rm -f "$out/ucrtbase_complex.o" "$out/ours.txt" "$out/wine_exports.txt" "$out/ucrtbase.def"
echo "built $out: icuuc.dll, ucrtbase.dll (its complex functions, the rest forwarded), ucrtwine.dll"
