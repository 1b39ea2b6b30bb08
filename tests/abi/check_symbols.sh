#!/usr/bin/env bash
# Usage: check_symbols.sh LIBOCTOCAP.so HEADERS_DIR CURRENT_HEADER
# Fails when a function declared by an old header, or by today's (inline ones aside), is not exported.
set -euo pipefail
lib="$1"; headers="$2"; current="$3"
exported="$(nm -D --defined-only "$lib" | awk '{print $3}' | sort -u)"
status=0
for h in "$headers"/*.h "$current"; do
  # Declarations (an old header declares the _init functions that today's makes inline: they stay exported).
  for f in $(grep -hoE '^OCTOCAP_API [^(]*\boctocap_[a-z0-9_]+\(' "$h" | grep -oE 'octocap_[a-z0-9_]+\($' | tr -d '(' | sort -u); do
    if ! grep -qx "$f" <<<"$exported"; then
      echo "missing export: $f (declared in $(basename "$h"))"; status=1
    fi
  done
done
[ $status = 0 ] && echo "every declared function is exported ($(wc -l <<<"$exported") exports)"
exit $status
