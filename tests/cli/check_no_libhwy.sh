#!/bin/sh
# The programs must not load libhwy.so: its static initializer costs every start 4-6 ms of CPU
# (runtime/simd/targets.hpp). Each program given must be a dynamic program whose NEEDED list names
# no libhwy. Exit 1 with the finding otherwise.
set -eu
status=0
for exe in "$@"; do
  needed=$(readelf -d "$exe" | sed -n 's/.*(NEEDED).*Shared library: \[\(.*\)\]/\1/p')
  if [ -z "$needed" ]; then
    echo "$exe: no NEEDED entries (expected a dynamically linked program)"
    status=1
  elif echo "$needed" | grep -q '^libhwy'; then
    echo "$exe: loads $(echo "$needed" | grep '^libhwy' | tr '\n' ' ')(expected no libhwy: runtime/simd/targets.hpp)"
    status=1
  else
    echo "$exe: $(echo "$needed" | wc -l) libraries, no libhwy"
  fi
done
exit $status
