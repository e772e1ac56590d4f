#!/usr/bin/env bash
# Compiles the portable core (firmware/core/) for the ESP family's Xtensa
# architecture with the embedded flags, and prints the code size per object
# and in total. Fails when anything does not compile (warnings included).
#
# The compiler is Debian's gcc-xtensa-lx106 (the ESP8266's core; the ESP32's
# is the LX6, same instruction set family). It ships no C library and no
# libstdc++: <cstdint>, <cmath>, <array> and even <math.h> are missing, and
# its <stdint.h> only works in freestanding mode. So the check compiles with
# -ffreestanding, which proves the core needs no library at all; the real
# ESP32 toolchain, which has one, compiles the same code unchanged.
#
# Usage: firmware/check_embedded.sh [OUTPUT_DIR]   (default: a temporary one)
# Override the tools with XTENSA_CXX and XTENSA_SIZE.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
core="$here/core"
cxx=${XTENSA_CXX:-xtensa-lx106-elf-g++}
size=${XTENSA_SIZE:-xtensa-lx106-elf-size}
for tool in "$cxx" "$size"; do
  command -v "$tool" >/dev/null || { echo "check_embedded: $tool not found (Debian: apt-get install gcc-xtensa-lx106)" >&2; exit 1; }
done

if [ $# -ge 1 ]; then
  out=$1
  mkdir -p "$out"
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
rm -f "$out"/*.o

flags=(-std=c++17 -ffreestanding -fno-exceptions -fno-rtti -Os -ffunction-sections -fdata-sections
       -Wall -Wextra -Wpedantic -Wshadow -Wold-style-cast -Wconversion -Wsign-conversion -Wdouble-promotion -Werror)

# One translation unit including every header, with the templates
# instantiated, so that header-only code is compiled too.
all_headers="$out/all_core_headers.cpp"
{
  for header in "$core"/*.h; do echo "#include \"$header\""; done
  echo "template class alplan::firmware::RingBuffer<float, 8>;"
  echo "template class alplan::firmware::ReadingQueue<4>;"
} >"$all_headers"

status=0
for source in "$all_headers" "$core"/*.cpp; do
  object="$out/$(basename "${source%.cpp}").o"
  if ! "$cxx" "${flags[@]}" -c "$source" -o "$object"; then
    echo "check_embedded: $(basename "$source") does not compile for Xtensa" >&2
    status=1
  fi
done
[ $status -eq 0 ] || exit $status

echo "Code size of firmware/core for xtensa-lx106 ($cxx ${flags[*]}):"
"$size" -t "$out"/*.o
