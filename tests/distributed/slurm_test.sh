#!/bin/sh
# scripts/shadergen-slurm on a one-node Slurm cluster this test starts itself: munged,
# slurmctld and slurmd with every key, socket, spool, state, pid and log file under the scratch
# folder (nothing in /etc/munge or /etc/slurm is read or written), and nginx as the WebDAV
# remote cache. Scenarios:
#   a. 4 shards + merge of split_second and of a generated 14-feature domain: the merged folder
#      is byte for byte a local --no-cache build.
#   b. shard task 2 fails and task 1 is cancelled while it runs: the script exits 1 naming
#      both and their logs; the merge never ran.
#   c. a signing secret (--remote-cache-secret-file), without --wait: the entries on the
#      server are signed and the merge, once the jobs are done, matches the local build.
#   d. no Slurm: shards 0, 1 and 3 of 4 run by hand; the merge with --require-remote-hits
#      --shards 4 exits 1 naming shard 2 (no record of it: before fetching any entry) and writes
#      nothing.
#   e. argument checks: usage errors exit 2, more shards than MaxArraySize exit 1 naming it.
# The jobs run with the script's shipped defaults: every run shares the one default cache folder,
# as on a shared $HOME, and scenario a checks that none of them used it (the script passes
# --no-cache to every shard and the merge).
#   usage: slurm_test.sh <shadergen executable | stand-in> <repository root> <scratch folder>
# "stand-in" runs the Slurm plumbing against a small sh imitation of `shadergen build --shard`
# (no compiling) for work on this test while shadergen itself is elsewhere.
# Needs root (munged and slurmd run as root here), exits 77 (skipped) otherwise or when Slurm,
# munge or nginx is missing (scripts/install-deps.sh --tests installs them).
set -eu
[ $# -eq 3 ] || { echo "usage: $0 <shadergen|stand-in> <repository root> <scratch folder>" >&2; exit 2; }
shadergen=$1
repo=$(cd "$2" && pwd)
work=$3
script=$repo/scripts/shadergen-slurm
PATH=$PATH:/usr/sbin:/sbin
export PATH

say() { echo "slurm_test: $*"; }
skip() { echo "slurm_test: skipped: $*"; exit 77; }
fail() {
    echo "slurm_test: FAIL: $*" >&2
    exit 1
}

[ "$(id -u)" -eq 0 ] || skip "needs root (it runs munged and slurmd)"
for tool in munged mungekey munge slurmctld slurmd sbatch squeue scontrol sinfo scancel nginx curl ss timeout; do
    command -v "$tool" >/dev/null || skip "$tool is not installed (scripts/install-deps.sh --tests installs slurm-wlm, munge and nginx)"
done

mkdir -p "$work"
work=$(cd "$work" && pwd)
# Daemons of an earlier run that was killed before its trap ran: each names this folder on its
# command line, so only those are stopped.
if [ -d "$work/run" ]; then
    for pidfile in "$work"/run/*.pid; do
        [ -f "$pidfile" ] || continue
        pid=$(cat "$pidfile")
        if [ -n "$pid" ] && tr '\0' ' ' <"/proc/$pid/cmdline" 2>/dev/null | grep -qF "$work/"; then
            kill "$pid" 2>/dev/null || true
        fi
    done
    sleep 1
fi
rm -rf "$work"
mkdir -p "$work/run" "$work/bin" "$work/caches" "$work/munge" "$work/slurm/state" "$work/slurm/spool" \
    "$work/slurm/log" "$work/nginx/data/cache" "$work/nginx/tmp" "$work/nginx/logs"
# munged refuses a socket folder that not everyone can enter, and a group- or world-writable
# one without the sticky bit (a umask of 002 would give that).
chmod 755 "$work" "$work/munge"

# Nothing may reach the user's caches or a remote cache named in the environment: sbatch hands
# this environment to every job.
unset SHADERGEN_REMOTE_CACHE SHADERGEN_REMOTE_CACHE_SECRET
SHADERGEN_CACHE_DIR=$work/caches/default
XDG_CACHE_HOME=$work/caches/xdg
export SHADERGEN_CACHE_DIR XDG_CACHE_HOME
export SHADERGEN_SLURM_POLL_SECONDS=1

daemons=""
script_pid=""
cleanup() {
    status=$?
    trap - EXIT INT TERM
    if [ -n "$script_pid" ]; then
        kill "$script_pid" 2>/dev/null || true
        wait "$script_pid" 2>/dev/null || true
    fi
    if [ -n "${SLURM_CONF:-}" ] && [ -f "$work/run/slurmctld.pid" ]; then
        scancel --user=root >/dev/null 2>&1 || true
        sleep 1
    fi
    for pid in $daemons; do kill "$pid" 2>/dev/null || true; done
    for pid in $daemons; do wait "$pid" 2>/dev/null || true; done
    [ -z "${short:-}" ] || rm -rf "$short"
    if [ "$status" -ne 0 ] && [ "$status" -ne 77 ]; then
        for log in "$work/slurm/log/slurmctld.log" "$work/slurm/log/slurmd.log" "$work/munge/munged.out" \
            "$work/nginx/logs/error.log"; do
            [ -s "$log" ] || continue
            echo "--- last lines of $log" >&2
            tail -n 15 "$log" >&2
        done
    fi
    exit "$status"
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# A TCP port on 127.0.0.1 nothing listens on, below Linux's ephemeral range.
taken_ports=""
free_port() {
    while :; do
        port=$((10000 + $(od -An -N2 -tu2 /dev/urandom | tr -d ' ') % 20000))
        case " $taken_ports " in *" $port "*) continue ;; esac
        [ -z "$(ss -Htln "sport = :$port")" ] && break
    done
    taken_ports="$taken_ports $port"
    echo "$port"
}

# Waits up to $1 seconds for the command in $2... to succeed.
wait_for() {
    limit=$1
    shift
    i=0
    while ! "$@" >/dev/null 2>&1; do
        i=$((i + 1))
        [ "$i" -le $((limit * 5)) ] || return 1
        sleep 0.2
    done
}

start=$(date +%s)
# Every daemon runs in the foreground under timeout, which passes the trap's TERM on and ends
# the daemon by itself should this test be killed before its trap runs.
lifetime="timeout 600"

# --- munge: its own key, socket, pid, seed and log; the system's munged is not involved.
mungekey --create --bits=1024 --keyfile="$work/munge/munge.key"
chmod 400 "$work/munge/munge.key"
socket=$work/munge/munge.socket
# A Unix socket's path holds at most 107 bytes: a deep build tree gets a short folder in /tmp.
if [ ${#socket} -gt 100 ]; then
    short=$(mktemp -d /tmp/shadergen-slurm-test.XXXXXX)
    chmod 755 "$short"
    socket=$short/munge.socket
fi
$lifetime munged --foreground --socket="$socket" --key-file="$work/munge/munge.key" --pid-file="$work/run/munged.pid" \
    --log-file="$work/munge/munged.log" --seed-file="$work/munge/munged.seed" >"$work/munge/munged.out" 2>&1 &
daemons="$daemons $!"
wait_for 10 munge --socket="$socket" --no-input || fail "munged did not start: $(cat "$work/munge/munged.out")"

# --- Slurm: one node, localhost, every CPU of this machine.
SLURM_CONF=$work/slurm/slurm.conf
export SLURM_CONF
ctld_port=$(free_port)
slurmd_port=$(free_port)
s=$work/slurm
# The node is "localhost" whatever this machine's hostname is: slurmd is told with -N.
# ProctrackType=linuxproc and TaskPlugin=none: no cgroups, which containers often lack.
# PlugStackConfig names an empty file so that /etc/slurm/plugstack.conf is not read.
cat >"$SLURM_CONF" <<EOF
ClusterName=shadergentest
SlurmctldHost=localhost(127.0.0.1)
SlurmctldPort=$ctld_port
SlurmdPort=$slurmd_port
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$socket
SlurmUser=root
SlurmdUser=root
StateSaveLocation=$s/state
SlurmdSpoolDir=$s/spool
SlurmctldPidFile=$work/run/slurmctld.pid
SlurmdPidFile=$work/run/slurmd.pid
SlurmctldLogFile=$s/log/slurmctld.log
SlurmdLogFile=$s/log/slurmd.log
PlugStackConfig=$s/plugstack.conf
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
MpiDefault=none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
JobAcctGatherType=jobacct_gather/none
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
MailProg=/bin/true
MaxArraySize=100
# Start jobs as soon as they are submitted or their dependency is met (default: within 3 s).
SchedulerParameters=batch_sched_delay=0
NodeName=localhost NodeAddr=127.0.0.1 CPUs=$(nproc) State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
EOF
: >"$s/plugstack.conf"
# -i: ignore state a killed earlier run may have left (there is none after the rm above).
$lifetime slurmctld -D -i -f "$SLURM_CONF" >"$s/log/slurmctld.out" 2>&1 &
daemons="$daemons $!"
$lifetime slurmd -D -f "$SLURM_CONF" -N localhost >"$s/log/slurmd.out" 2>&1 &
daemons="$daemons $!"
node_idle() { [ "$(sinfo -h -n localhost -o %t 2>/dev/null)" = idle ]; }
wait_for 30 node_idle || fail "the Slurm node did not come up idle: sinfo says '$(sinfo -h -o '%t %E' 2>&1)'"

# The cluster runs a job at all.
job=$(sbatch --parsable --output="$work/hello-%j.out" --wrap 'echo hello from $SLURM_JOB_ID')
job_done() { [ -z "$(squeue -h -j "$1" 2>/dev/null)" ]; }
wait_for 30 job_done "$job" || fail "the first test job $job did not finish"
grep -q "hello from $job" "$work/hello-$job.out" 2>/dev/null || fail "the first test job $job printed nothing"

# --- nginx: the WebDAV remote cache (the configuration of tests/support's NginxServer).
nginx_port=$(free_port)
n=$work/nginx
cat >"$n/nginx.conf" <<EOF
daemon off;
master_process off;
error_log $n/logs/error.log warn;
pid $work/run/nginx.pid;
events { worker_connections 256; }
http {
  access_log $n/logs/access.log;
  client_body_temp_path $n/tmp/body;
  proxy_temp_path $n/tmp/proxy;
  fastcgi_temp_path $n/tmp/fastcgi;
  uwsgi_temp_path $n/tmp/uwsgi;
  scgi_temp_path $n/tmp/scgi;
  server {
    listen 127.0.0.1:$nginx_port;
    root $n/data;
    location /cache/ {
      dav_methods PUT;
      create_full_put_path on;
      client_max_body_size 0;
    }
  }
}
EOF
$lifetime nginx -p "$n" -e "$n/logs/error.log" -c "$n/nginx.conf" >"$n/logs/nginx.out" 2>&1 &
daemons="$daemons $!"
url=http://127.0.0.1:$nginx_port/cache
nginx_up() { curl -s -o /dev/null "$url/"; }
wait_for 10 nginx_up || fail "nginx did not start: $(cat "$n/logs/nginx.out" "$n/logs/error.log" 2>/dev/null)"
say "cluster, munged and nginx up in $(($(date +%s) - start)) s (slurmctld :$ctld_port, cache $url)"

# --- The shadergen under test.
if [ "$shadergen" = stand-in ]; then
    # Imitates the CLI contract: a source is a line of the spec file; shard I of N owns
    # line numbers = I (mod N) and PUTs them; the merge GETs every one and names each shard
    # with sources missing; a full build writes the same output folder.
    shadergen=$work/bin/stand-in-shadergen
    cat >"$shadergen" <<'EOF'
#!/bin/sh
[ "$1" = build ] || exit 2
shift
case " $* " in *" --help "*) echo "stand-in: --shard I/N --require-remote-hits"; echo "  --shards UINT:UINT in [1 - 4096]"; exit 0 ;; esac
spec="" out="" shard="" shards="" url="" secret="" require=0
while [ $# -gt 0 ]; do
    case $1 in
        --out) out=$2; shift 2 ;;
        --shard) shard=$2; shift 2 ;;
        --shards) shards=$2; shift 2 ;;
        --remote-cache) url=$2; shift 2 ;;
        --remote-cache-secret-file) secret=$(cat "$2"); shift 2 ;;
        --require-remote-hits) require=1; shift ;;
        --cache-dir | -j | --remote-cache-budget) shift 2 ;;
        --remote-cache-budget=* | --verbose) shift ;;
        --no-cache) shift ;;
        -*) echo "stand-in: unknown option $1" >&2; exit 2 ;;
        *) spec=$1; shift ;;
    esac
done
sign() { if [ -n "$secret" ]; then printf 'SGHMAC1 %s\n' "$(printf '%s' "$secret" | md5sum | cut -c1-8)"; fi; }
key() { printf '%s' "$1" | md5sum | cut -c1-16; }
if [ -n "$shard" ]; then
    index=${shard%/*} count=${shard#*/}
    [ "$index" -lt "$count" ] || exit 2
    line=0
    while IFS= read -r text; do
        if [ $((line % count)) -eq "$index" ]; then
            k=$(key "$line:$text")
            { printf '%s\n' "$text"; sign; } | curl -sf -T - "$url/${k%${k#??}}/$k" || exit 1
        fi
        line=$((line + 1))
    done <"$spec"
    exit 0
fi
if [ "$require" -eq 1 ]; then
    line=0 missing=0
    : >"$out.missing"
    while IFS= read -r text; do
        k=$(key "$line:$text")
        curl -sf -o /dev/null "$url/${k%${k#??}}/$k" || { missing=$((missing + 1)); echo $((line % ${shards:-1})) >>"$out.missing"; }
        line=$((line + 1))
    done <"$spec"
    if [ "$missing" -gt 0 ]; then
        echo "stand-in: error: $missing sources missing on the remote cache" >&2
        [ -z "$shards" ] || sort -n "$out.missing" | uniq -c | while read -r c i; do echo "shard $i/$shards: $c sources missing" >&2; done
        rm -f "$out.missing"
        exit 1
    fi
    rm -f "$out.missing"
fi
mkdir -p "$out" && cp "$spec" "$out/manifest.json"
EOF
    chmod +x "$shadergen"
else
    shadergen=$(cd "$(dirname "$shadergen")" && pwd)/$(basename "$shadergen")
    [ -x "$shadergen" ] || fail "$shadergen is not an executable"
    "$shadergen" build --help 2>/dev/null | grep -q -- '--shard' ||
        skip "$shadergen has no 'build --shard' option yet"
fi

# bin/sg: shadergen as the script runs it, logging its arguments. bin/sg-fail: the same, but
# shard 2 of 4 fails and shard 1 of 4 hangs (until the test cancels it).
cat >"$work/bin/sg" <<EOF
#!/bin/sh
printf '%s\n' "\$*" >>"$work/argv.log"
exec "$shadergen" "\$@"
EOF
cat >"$work/bin/sg-fail" <<EOF
#!/bin/sh
case " \$* " in
    *" --shard 2/4 "*) echo "sg-fail: shard 2 fails on purpose" >&2; exit 1 ;;
    *" --shard 1/4 "*) : >"$work/hang-started"; exec sleep 600 ;;
esac
exec "$work/bin/sg" "\$@"
EOF
chmod +x "$work/bin/sg" "$work/bin/sg-fail"
: >"$work/argv.log"

# --- A 14-feature domain: one #ifdef block per feature; rule 1 keeps the two groups of seven
# features apart and rule 2 forbids one pair, leaving 223 of the 16,384 raw IDs, each its own
# source (a few hundred compiles: seconds, not minutes, even under ASan).
gen=$work/gen14
mkdir -p "$gen"
{
    printf '#version 450\n// Generated by tests/distributed/slurm_test.sh.\n'
    printf 'layout(location = 0) out vec4 out_colour;\nvoid main() {\n    vec4 c = vec4(0.0);\n'
    f=0
    while [ $f -lt 14 ]; do
        printf '#ifdef USE_F%02d\n    c += vec4(%d.0 / 16.0, 0.0, 0.0, 0.0);\n#endif\n' $f $((f + 1))
        f=$((f + 1))
    done
    printf '    out_colour = c;\n}\n'
} >"$gen/gen14.frag"
{
    printf '{\n  "format": 1,\n  "name": "gen14",\n'
    printf '  "description": "slurm_test: 14 features, two exclusive groups of seven",\n'
    printf '  "uber_shader": { "path": "gen14.frag", "stage": "fragment" },\n  "raw": {\n    "features": [\n'
    f=0
    while [ $f -lt 14 ]; do
        [ $f -eq 0 ] || printf ',\n'
        printf '      { "name": "F%02d", "bit": %d, "define": "USE_F%02d" }' $f $f $f
        f=$((f + 1))
    done
    printf '\n    ],\n    "impossible": [\n'
    printf '      { "when": "(F00 || F01 || F02 || F03 || F04 || F05 || F06) && (F07 || F08 || F09 || F10 || F11 || F12 || F13)" },\n'
    printf '      { "when": "F05 && F06" }\n    ]\n  },\n'
    printf '  "optimised": {\n    "bits": [\n'
    printf '      { "name": "A", "bit": 0, "when": "F00 || F01" },\n'
    printf '      { "name": "B", "bit": 1, "when": "F02" }\n    ],\n'
    printf '    "variants": [\n'
    printf '      { "when": "A", "raw_features": ["F00"] },\n'
    printf '      { "when": "B", "raw_features": ["F02"] }\n    ]\n  }\n}\n'
} >"$gen/gen14.json"

split_second=$repo/permutations/split_second.json
mkdir -p "$work/local" "$work/out" "$work/logs"

# A plain local build to compare with: $1 name, $2 spec.
local_build() {
    t=$(date +%s)
    "$shadergen" build "$2" --out "$work/local/$1" --no-cache -j 2 --cache-dir "$work/caches/local-$1" \
        >"$work/logs/local-$1.log" 2>&1 || fail "local build of $1 failed: $(cat "$work/logs/local-$1.log")"
    say "local build of $1: $(($(date +%s) - t)) s"
}

# Starts scripts/shadergen-slurm in the background (so that a signal to this test is handled at
# once, and the trap can stop it): $1 name (logs/<name>.out, .err), the rest its arguments.
start_script() {
    script_name=$1
    shift
    script_start=$(date +%s)
    timeout 150 "$script" "$@" >"$work/logs/$script_name.out" 2>"$work/logs/$script_name.err" &
    script_pid=$!
}

# Waits for it; its exit status goes to logs/<name>.rc.
finish_script() {
    rc=0
    wait "$script_pid" || rc=$?
    script_pid=""
    echo "$rc" >"$work/logs/$script_name.rc"
    say "shadergen-slurm $script_name: exit $rc in $(($(date +%s) - script_start)) s"
}

run_script() {
    start_script "$@"
    finish_script
}

show() { cat "$work/logs/$1.out" "$work/logs/$1.err"; }

# Fails unless the merged folder $1 is the local build $2, byte for byte.
same_output() {
    [ -d "$1" ] || fail "no merged output $1"
    diff -r "$1" "$work/local/$2" >"$work/logs/diff-$2.txt" 2>&1 ||
        fail "merged $1 differs from the local build of $2: $(head -n 20 "$work/logs/diff-$2.txt")"
}

# --- e. Argument checks (nothing is submitted).
expect_rc() { # $1 expected exit, $2 text the error must contain, $3... arguments
    want=$1 text=$2
    shift 2
    rc=0
    "$script" "$@" >"$work/logs/args.out" 2>"$work/logs/args.err" || rc=$?
    [ "$rc" -eq "$want" ] || fail "shadergen-slurm $*: exit $rc, expected $want: $(cat "$work/logs/args.err")"
    grep -qF -- "$text" "$work/logs/args.err" ||
        fail "shadergen-slurm $*: the error does not say '$text': $(cat "$work/logs/args.err")"
}
"$script" --help | grep -q '^Usage: shadergen-slurm SPEC' || fail "--help prints no usage"
expect_rc 2 "--remote-cache URL is required" "$split_second" --out "$work/out/x" --shards 4 --shadergen "$work/bin/sg"
expect_rc 2 "--shards must be an integer from 1 to 4096" "$split_second" --out "$work/out/x" --shards 0 --remote-cache "$url/x" \
    --shadergen "$work/bin/sg"
expect_rc 2 "--shards must be an integer from 1 to 4096" "$split_second" --out "$work/out/x" --shards 4097 --remote-cache "$url/x" \
    --shadergen "$work/bin/sg"
expect_rc 2 "is not a readable file" "$work/no-such.json" --out "$work/out/x" --shards 4 --remote-cache "$url/x"
expect_rc 2 "--out DIR is required" "$split_second" --shards 4 --remote-cache "$url/x"
expect_rc 2 "http:// or https://" "$split_second" --out "$work/out/x" --shards 4 --remote-cache "ftp://x/y"
expect_rc 2 "sets the output, the shard and the remote cache itself" "$split_second" --out "$work/out/x" --shards 4 \
    --remote-cache "$url/x" --build-arg=--remote-cache-readonly
expect_rc 2 "is not on PATH" "$split_second" --out "$work/out/x" --shards 4 --remote-cache "$url/x" --shadergen no-such-shadergen
expect_rc 2 "--tasks must be an integer from 1 to --shards (4)" "$split_second" --out "$work/out/x" --shards 4 --tasks 5 \
    --remote-cache "$url/x" --shadergen "$work/bin/sg"
expect_rc 1 "MaxArraySize is 100" "$split_second" --out "$work/out/x" --shards 101 --remote-cache "$url/x" --shadergen "$work/bin/sg"
grep -qF "slurm.conf" "$work/logs/args.err" || fail "the MaxArraySize error does not say where to raise it"
[ -z "$(squeue -h)" ] || fail "an argument check submitted jobs: $(squeue)"
[ ! -e "$work/out/x" ] && [ ! -e "$work/out/x.slurm" ] || fail "an argument check created $work/out/x"
say "e. argument checks: ok"

# --- a. 4 shards + merge, compared with a local build.
local_build split_second "$split_second"
local_build gen14 "$gen/gen14.json"
# gen14 also passes a build argument through to every job (it does not change the output).
for domain in split_second gen14; do
    if [ "$domain" = split_second ]; then spec=$split_second extra=""; else spec=$gen/gen14.json extra=--verbose; fi
    run_script "a-$domain" "$spec" --out "$work/out/a-$domain" --shards 4 --remote-cache "$url/a" \
        --shadergen "$work/bin/sg" ${extra:+--build-arg=$extra} --wait
    [ "$(cat "$work/logs/a-$domain.rc")" -eq 0 ] || fail "a: shadergen-slurm on $domain failed: $(show "a-$domain")"
    same_output "$work/out/a-$domain" "$domain"
    for i in 0 1 2 3; do
        grep -qF -- "build $spec --shard $i/4 --remote-cache $url/a --no-cache${extra:+ $extra}" \
            "$work/argv.log" || fail "a: no shard $i/4 of $domain ran: $(cat "$work/argv.log")"
    done
    grep -qF -- "build $spec --out $work/out/a-$domain --remote-cache $url/a --no-cache --require-remote-hits --shards 4${extra:+ $extra}" \
        "$work/argv.log" || fail "a: the merge of $domain did not run as expected: $(cat "$work/argv.log")"
    set -- "$work/out/a-$domain.slurm/logs/"shard-*_3.log
    [ -f "$1" ] || fail "a: no log of task 3 in $work/out/a-$domain.slurm/logs"
done
# Every job shared the default cache folder (SHADERGEN_CACHE_DIR, as a shared $HOME would give
# them) and none used it.
[ -z "$(find "$work/caches/default" "$work/caches/xdg" -type f 2>/dev/null | head -n 1)" ] ||
    fail "a: the jobs wrote the shared default cache: $(find "$work/caches/default" "$work/caches/xdg" -type f | head -n 5)"
say "a. 4 shards + merge of split_second and gen14 match the local builds; no job used the shared local cache"

# --- b. Shard task 2 fails, task 1 is cancelled while it runs (so it writes no status): exit 1
# naming both and their logs, the merge never runs.
start_script b "$gen/gen14.json" --out "$work/out/b" --shards 4 --remote-cache "$url/a" \
    --shadergen "$work/bin/sg-fail" --wait
wait_for 60 test -f "$work/hang-started" || fail "b: shard task 1 did not start"
array=$(sed -n 's/^array=//p' "$work/out/b.slurm/jobs")
scancel "${array}_1"
finish_script
[ "$(cat "$work/logs/b.rc")" -eq 1 ] || fail "b: a failed shard task did not make shadergen-slurm exit 1: $(show b)"
grep -qF "shard task 2 of 4 failed (exit 1): log $work/out/b.slurm/logs/shard-${array}_2.log" "$work/logs/b.err" ||
    fail "b: the error does not name task 2 and its log: $(show b)"
grep -qF "shard task 1 of 4 ended without finishing (Slurm state CANCELLED" "$work/logs/b.err" ||
    fail "b: the error does not name the cancelled task 1: $(show b)"
grep -qF "2 of 4 shard tasks failed" "$work/logs/b.err" || fail "b: no summary of the failed tasks: $(show b)"
if grep -q "shard task [03] of 4" "$work/logs/b.err"; then fail "b: a task that succeeded is named as failed: $(show b)"; fi
grep -q "shard 2 fails on purpose" "$work"/out/b.slurm/logs/shard-*_2.log || fail "b: task 2's log lacks its error"
[ ! -e "$work/out/b" ] || fail "b: the merge wrote $work/out/b although a shard failed"
if grep -qF -- "--out $work/out/b " "$work/argv.log"; then fail "b: the merge ran although a shard failed"; fi
merge=$(sed -n 's/^merge=//p' "$work/out/b.slurm/jobs")
[ ! -e "$work/out/b.slurm/logs/merge-$merge.log" ] || fail "b: the merge job $merge started"
[ -z "$(squeue -h)" ] || fail "b: jobs left in the queue: $(squeue)"
say "b. a failed and a cancelled shard: exit 1 naming tasks 2 and 1, merge cancelled"

# --- c. A signing secret, without --wait: the jobs are left to finish, then checked. The
# output folder's name has a space and a quote, which the generated job scripts must keep.
c_out="$work/out/c d'x"
printf 'slurm-test-secret-%s\n' "$(od -An -N8 -tx8 /dev/urandom | tr -d ' ')" >"$work/secret"
chmod 600 "$work/secret"
run_script c "$split_second" --out "$c_out" --shards 4 --tasks 2 --remote-cache "$url/c" \
    --remote-cache-secret-file "$work/secret" --shadergen "$work/bin/sg"
[ "$(cat "$work/logs/c.rc")" -eq 0 ] || fail "c: shadergen-slurm without --wait failed: $(show c)"
# --tasks 2: Slurm runs at most 2 of the 4 shard tasks at once (the array's throttle).
c_array=$(sed -n 's/^array=//p' "$c_out.slurm/jobs")
scontrol show job "$c_array" | grep -q "ArrayTaskThrottle=2" ||
    fail "c: --tasks 2 did not throttle the array: $(scontrol show job "$c_array" | head -n 5)"
grep -q "squeue -j [0-9]*,[0-9]*" "$work/logs/c.out" || fail "c: no way to watch the jobs printed: $(show c)"
queue_empty() { [ -z "$(squeue -h 2>/dev/null)" ]; }
wait_for 150 queue_empty || fail "c: the jobs did not finish: $(squeue)"
same_output "$c_out" split_second
grep -qF -- "--require-remote-hits --shards 4" "$work/argv.log" &&
    grep -qF -- "--out $c_out --remote-cache $url/c --remote-cache-secret-file $work/secret --no-cache --require-remote-hits" \
        "$work/argv.log" || fail "c: the merge did not get the secret file: $(cat "$work/argv.log")"
[ "$(grep -cF -- "--remote-cache $url/c --remote-cache-secret-file $work/secret" "$work/argv.log")" -eq 5 ] ||
    fail "c: not all 4 shards and the merge got the secret file: $(cat "$work/argv.log")"
entries=0
for entry in "$n"/data/cache/c/??/*; do
    [ -f "$entry" ] || continue
    entries=$((entries + 1))
    grep -q SGHMAC1 "$entry" || fail "c: $entry on the server is not signed"
done
[ "$entries" -gt 0 ] || fail "c: nothing was uploaded to $url/c"
if grep -rqF "$(cat "$work/secret")" "$c_out.slurm" "$work/logs"; then fail "c: the secret appears in a log or job script"; fi
say "c. with a secret file: $entries signed entries, merge matches the local build"

# --- d. The merge alone refuses a cache that lacks shard 2's sources.
for i in 0 1 3; do
    "$shadergen" build "$split_second" --shard "$i/4" --remote-cache "$url/d" -j 2 --cache-dir "$work/caches/d-$i" \
        >"$work/logs/d-$i.log" 2>&1 || fail "d: shard $i/4 run by hand failed: $(cat "$work/logs/d-$i.log")"
done
rc=0
"$shadergen" build "$split_second" --out "$work/out/d" --remote-cache "$url/d" --require-remote-hits --shards 4 \
    -j 2 --cache-dir "$work/caches/d-merge" >"$work/logs/d-merge.log" 2>&1 || rc=$?
[ "$rc" -eq 1 ] || fail "d: the merge without shard 2 exited $rc, expected 1: $(cat "$work/logs/d-merge.log")"
grep -qE "shard 2/4: (no record of it on the server|[1-9][0-9]* sources? missing)" "$work/logs/d-merge.log" ||
    fail "d: the merge's error does not name shard 2: $(cat "$work/logs/d-merge.log")"
if grep -q "shard [013]/4" "$work/logs/d-merge.log"; then fail "d: the merge names a shard that ran: $(cat "$work/logs/d-merge.log")"; fi
[ ! -e "$work/out/d" ] || fail "d: the refused merge wrote $work/out/d"
say "d. the merge refuses a cache missing shard 2: $(grep 'shard 2/4' "$work/logs/d-merge.log")"

say "passed in $(($(date +%s) - start)) s"
