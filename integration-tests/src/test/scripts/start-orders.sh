#!/usr/bin/env bash
# Starts the README tour's run in every order the tour allows and checks that each starts, runs and
# ends the same, with no connection refused: an Environment on empty-room.xml and two Wander robots,
# each a JVM of its own, started as the tour starts them (`robosim env WORLD &`, `robosim robot ... &`),
# the Environment first or the robots first, 0 to 3 s apart. The cases run one after the other, or
# TOGETHER=N of them at once (a harsher load: each case is three JVMs starting). Optional cases: a ControlPanel attached before its
# Environment starts (PANEL=1, needs a display), and an ARIA client doing ARIA's handshake on a
# Pioneer port (PIONEER_CLIENT).
#
# usage: start-orders.sh OUT_DIR PORT...
#   OUT_DIR  a folder for each case's logs
#   PORT...  free ports, three per case (robot, viewer, Pioneer: the Pioneer case takes that one and the next)
# environment:
#   ROBOSIM         the launcher (default: bin/robosim of this clone)
#   STEPS           steps per run (default 50)
#   CASE_TIMEOUT    seconds any one command may take (default 300)
#   PANEL           1 to add the ControlPanel case
#   CASES           the cases to run, by name (default: all); e.g. CASES="env-0s robots-3s"
#   TOGETHER        how many cases run at once (default 1)
#   PIONEER_CLIENT  a program, run as PIONEER_CLIENT HOST PORT, that does ARIA's handshake with ARIA's
#                   patience for robot r2 on its Pioneer port, reads status packets and exits 0; set to
#                   add the Pioneer case
# prints one line per case (how long its start took) and exits 0 only if every case passed.
set -uo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../../.." && pwd)"
ROBOSIM="${ROBOSIM:-$ROOT/bin/robosim}"
STEPS="${STEPS:-50}"
CASE_TIMEOUT="${CASE_TIMEOUT:-300}"
WORLD="$ROOT/testLoadFiles/environment/empty-room.xml"
OUT="${1:?usage: start-orders.sh OUT_DIR PORT...}"
shift
PORTS=("$@")

now() { date +%s.%N; }
robosim() { timeout --kill-after=10 "$CASE_TIMEOUT" "$ROBOSIM" "$@"; }

# case NAME FIRST DELAY: FIRST (env or robots) starts, DELAY seconds later the other
run_case() {
  local name="$1" first="$2" delay="$3" rp="$4" vp="$5" pp="$6"
  local dir="$OUT/$name"
  mkdir -p "$dir"
  local started env_pid pids=() names=()
  started="$(now)"
  start_env() {
    local extra=()
    # every robot of the world is offered on a Pioneer port, r1 on PORT and r2 on PORT+1; r1's program
    # takes it over the robot port instead
    [ "$name" = pioneer ] && extra=(--pioneer-port "$pp")
    robosim env "$WORLD" --steps "$STEPS" --robot-port "$rp" --viewer-port "$vp" "${extra[@]}" \
      >"$dir/env.out" 2>"$dir/env.err" &
    env_pid=$!
  }
  start_robots() {
    for r in r1 r2; do
      if [ "$name" = pioneer ] && [ "$r" = r2 ]; then
        # as with MobileSim, an ARIA program is started once the simulator says its ports are open:
        # ARIA connects once and does not try again
        until grep -q "^Pioneer ports on" "$dir/env.out" 2>/dev/null; do
          kill -0 "$env_pid" 2>/dev/null || break
          sleep 0.1
        done
        timeout --kill-after=10 "$CASE_TIMEOUT" "$PIONEER_CLIENT" 127.0.0.1 "$((pp + 1))" >"$dir/$r.out" \
          2>"$dir/$r.err" &
      else
        robosim robot robosim.examples.wander.Wander "$r" localhost "$rp" >"$dir/$r.out" 2>"$dir/$r.err" &
      fi
      pids+=($!)
      names+=("$r")
    done
  }
  if [ "$name" = panel ]; then
    robosim panel --attach --viewer-port "$vp" --robot-port "$rp" >"$dir/panel.out" 2>"$dir/panel.err" &
    local panel_pid=$!
    sleep "$delay"
  fi
  if [ "$first" = env ]; then start_env; sleep "$delay"; start_robots
  else start_robots; sleep "$delay"; start_env; fi
  # the start took until the Environment's run began
  local begun=""
  while kill -0 "$env_pid" 2>/dev/null; do
    if grep -q "all robots connected" "$dir/env.err" 2>/dev/null; then begun="$(now)"; break; fi
    sleep 0.1
  done
  local failed=()
  wait "$env_pid" || failed+=("env exited $?")
  local i
  for i in "${!pids[@]}"; do
    wait "${pids[$i]}" || failed+=("${names[$i]} exited $?")
  done
  if [ "$name" = panel ]; then
    # the panel followed the run: it is stopped now, as a user closes it
    kill "$panel_pid" 2>/dev/null; wait "$panel_pid" 2>/dev/null
  fi
  for r in r1 r2; do
    # the ARIA client reads its status packets and leaves: its robot stands to the end
    [ "$name" = pioneer ] && [ "$r" = r2 ] && continue
    grep -q "^robot $r: .* ran to the end" "$dir/env.out" || failed+=("the report does not say $r ran to the end")
  done
  if [ "$name" = pioneer ]; then
    grep -q "^robot r2: .* its ARIA client left" "$dir/env.out" || failed+=("the report does not say r2's client left")
  fi
  if [ "$name" = panel ]; then
    grep -q "detached from .* up to step $STEPS, ended: done" "$dir/panel.err" \
      || failed+=("the panel did not follow the run to its end")
  fi
  if grep -il "refus" "$dir"/*.out "$dir"/*.err >/dev/null 2>&1; then
    failed+=("refused: $(grep -ih "refus" "$dir"/*.out "$dir"/*.err | head -n 3 | tr '\n' ' ')")
  fi
  grep "^robot r[12]: " "$dir/env.out" >"$dir/report" 2>/dev/null
  local took="?"
  [ -n "$begun" ] && took="$(awk -v a="$started" -v b="$begun" 'BEGIN { printf "%.1f", b - a }')"
  if [ ${#failed[@]} -eq 0 ]; then
    printf 'case %-10s ok: the run began %s s after the first command\n' "$name" "$took" >"$dir/result"
  else
    printf 'case %-10s FAILED: %s (logs in %s)\n' "$name" "$(IFS='; '; echo "${failed[*]}")" "$dir" >"$dir/result"
    # the end of every log of the case, so that a failure far away (CI) can be read from the output
    for f in "$dir"/*.out "$dir"/*.err; do
      [ -s "$f" ] || continue
      echo "  --- $(basename "$f"), last lines:" >>"$dir/result"
      tail -n 6 "$f" | cut -c1-400 | sed 's/^/  | /' >>"$dir/result"
    done
  fi
}

cases=("env-0s env 0" "env-1s env 1" "env-3s env 3" "robots-0s robots 0" "robots-1s robots 1.5" "robots-3s robots 3")
[ "${PANEL:-}" = 1 ] && cases+=("panel env 1")
[ -n "${PIONEER_CLIENT:-}" ] && cases+=("pioneer env 1")
if [ -n "${CASES:-}" ]; then
  chosen=()
  for c in "${cases[@]}"; do
    read -r name _ <<<"$c"
    case " $CASES " in *" $name "*) chosen+=("$c") ;; esac
  done
  cases=("${chosen[@]}")
fi
if [ ${#PORTS[@]} -lt $((3 * ${#cases[@]})) ]; then
  echo "start-orders.sh: ${#cases[@]} cases need $((3 * ${#cases[@]})) free ports, got ${#PORTS[@]}" >&2
  exit 2
fi
k=0
jobs_=()
for c in "${cases[@]}"; do
  read -r name first delay <<<"$c"
  run_case "$name" "$first" "$delay" "${PORTS[$k]}" "${PORTS[$((k + 1))]}" "${PORTS[$((k + 2))]}" &
  jobs_+=($!)
  if [ ${#jobs_[@]} -ge "${TOGETHER:-1}" ]; then
    for j in "${jobs_[@]}"; do wait "$j"; done
    jobs_=()
  fi
  k=$((k + 3))
done
for j in "${jobs_[@]+"${jobs_[@]}"}"; do wait "$j"; done
status=0
reference=""
for c in "${cases[@]}"; do
  read -r name _ <<<"$c"
  if [ -f "$OUT/$name/result" ]; then cat "$OUT/$name/result"; else echo "case $name FAILED: no result"; status=1; fi
  grep -q FAILED "$OUT/$name/result" 2>/dev/null && status=1
  # every order gives the same run: the robots' poses, distances and collisions at the end
  [ "$name" = pioneer ] && continue
  if [ -z "$reference" ]; then reference="$name"
  elif ! cmp -s "$OUT/$reference/report" "$OUT/$name/report"; then
    echo "case $name FAILED: its run differs from case $reference's:"; diff "$OUT/$reference/report" "$OUT/$name/report"
    status=1
  fi
done
exit $status
