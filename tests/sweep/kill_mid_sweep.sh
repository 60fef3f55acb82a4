# Sourced by the sweep scripts. kill_mid_sweep DIR PID: waits for a few finished runs in
# DIR/journal.csv, kills the sweep PID without warning (kill -9), and checks that it had not
# written its result files yet.
kill_mid_sweep() {
  local dir=$1 pid=$2 lines
  for _ in $(seq 1 2000); do
    lines=$(wc -l < "$dir/journal.csv" 2>/dev/null || echo 0)
    [ "$lines" -ge 4 ] && break
    sleep 0.005
  done
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
  if [ -f "$dir/runs.csv" ]; then echo "results written before the sweep finished"; exit 1; fi
}
