/* pyconfig.h for building the emulator's compiled kernel as an abi3 (limited API) extension of
 * the Windows CPython with mingw-w64 on Linux (tools/windows/ci.sh, build_kernel): the platform
 * part that CPython's PC/pyconfig.h gives an MSVC build, cut to what the limited API's headers
 * read (64-bit Windows, GCC), used with the Linux host Python's other headers (3.11 or newer:
 * the limited API of 3.11 is the same on every platform). */
#ifndef Py_CONFIG_H
#define Py_CONFIG_H
#define MS_WIN32
#define MS_WIN64
#define MS_WINDOWS
#define NT_THREADS
#define WITH_THREAD
#define Py_ENABLE_SHARED 1
#define HAVE_DECLSPEC_DLL
#define PLATFORM "win32"
#define COMPILER "[gcc]"
#include <basetsd.h>
typedef __int64 Py_ssize_t;
typedef Py_ssize_t ssize_t;
#define HAVE_PY_SSIZE_T 1
#define HAVE_SSIZE_T 1
#define SIZEOF_SHORT 2
#define SIZEOF_INT 4
#define SIZEOF_LONG 4
#define SIZEOF_LONG_LONG 8
#define SIZEOF_DOUBLE 8
#define SIZEOF_FLOAT 4
#define SIZEOF_VOID_P 8
#define SIZEOF_SIZE_T 8
#define SIZEOF_TIME_T 8
#define SIZEOF_WCHAR_T 2
#define SIZEOF__BOOL 1
#define SIZEOF_OFF_T 4
#define SIZEOF_FPOS_T 8
#define SIZEOF_HKEY 8
#define SIZEOF_PID_T SIZEOF_INT
#define ALIGNOF_SIZE_T 8
#define ALIGNOF_MAX_ALIGN_T 8
#define STDC_HEADERS 1
#define HAVE_WCHAR_H 1
#define HAVE_SYS_STAT_H 1
#define HAVE_STDDEF_H 1
#define HAVE_ERRNO_H 1
#define HAVE_SIGNAL_H 1
#define WORD_BIT 32
#define PY_FORMAT_SIZE_T "I64"
#endif
