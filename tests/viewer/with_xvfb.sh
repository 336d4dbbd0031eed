#!/usr/bin/env bash
# with_xvfb.sh COMMAND...: runs COMMAND with DISPLAY set to a new Xvfb server of its own (a free
# display number picked by Xvfb itself, -displayfd), and stops the server afterwards.
set -euo pipefail
command -v Xvfb >/dev/null || { echo "with_xvfb.sh: Xvfb is not installed (Debian package xvfb)" >&2; exit 1; }
fifo_dir=$(mktemp -d)
trap 'rm -rf "$fifo_dir"' EXIT
Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$fifo_dir/display" 2>"$fifo_dir/log" &
xvfb=$!
stop() { kill "$xvfb" 2>/dev/null || true; wait "$xvfb" 2>/dev/null || true; rm -rf "$fifo_dir"; }
trap stop EXIT
for _ in $(seq 100); do
  [[ -s "$fifo_dir/display" ]] && break
  kill -0 "$xvfb" 2>/dev/null || { echo "with_xvfb.sh: Xvfb did not start: $(tail -1 "$fifo_dir/log")" >&2; exit 1; }
  sleep 0.1
done
[[ -s "$fifo_dir/display" ]] || { echo "with_xvfb.sh: Xvfb gave no display number" >&2; exit 1; }
export DISPLAY=":$(head -1 "$fifo_dir/display")"
status=0
"$@" || status=$?
exit "$status"
