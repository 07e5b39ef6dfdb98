#!/usr/bin/env bash
# fsi spy: LCM's lcm-spy on the project's messages, decoded with the Java types the
# build makes from proto/fsi.lcm (build/java/fsi_lcmtypes.jar, installed to
# share/fsi/java; they need Debian's liblcm-java and a JDK).
#
# A run's traffic never leaves its private network namespace, so lcm-spy watches a
# traffic log (`fsi run --log-traffic`) played back in a namespace of its own: the
# player and lcm-spy share a loopback-only network there (the way `fsi run` does it,
# launch/private_network.c) and nothing reaches the machine's network. The java
# command is spelled out here: Debian's lcm-spy wrapper passes -Xincgc, which
# OpenJDK 17 refuses.
set -euo pipefail

usage() {
  cat <<'EOF'
usage: fsi spy LOG [--speed X]   lcm-spy on a traffic log (fsi run --log-traffic), with
                                 the log player's window (play, pause, seek), or played
                                 once at X times real time with --speed
       fsi spy --lcm-url URL     lcm-spy alone on an LCM network of your own (a run
                                 started with fsi run --lcm-url URL)
Both open windows (an X display is needed). Types from $FSI_LCMTYPES_JAR, or from
../share/fsi/java/fsi_lcmtypes.jar beside this program when installed.
EOF
}
die() { echo "fsi spy: $*" >&2; exit 2; }

# Where the player and lcm-spy meet, inside the private namespace only.
PRIVATE_URL="udpm://239.255.76.67:7667?ttl=0&recv_buf_size=4194304"
LCM_JAR=/usr/share/java/lcm.jar
# lcm-spy draws its message views with jchart2d (Debian's libjchart2d-java).
CHART_JAR=/usr/share/java/jchart2d.jar

log="" speed="" url=""
while [ $# -gt 0 ]; do
  case "$1" in
    -h|--help) usage; exit 0 ;;
    --speed) [ $# -ge 2 ] || die "--speed needs a number"; speed="$2"; shift ;;
    --speed=*) speed="${1#--speed=}" ;;
    --lcm-url) [ $# -ge 2 ] || die "--lcm-url needs a URL"; url="$2"; shift ;;
    --lcm-url=*) url="${1#--lcm-url=}" ;;
    -*) die "unknown option '$1' (fsi spy --help)" ;;
    *) [ -z "$log" ] || die "one log at a time"; log="$1" ;;
  esac
  shift
done
[ -n "$log" ] || [ -n "$url" ] || { usage >&2; exit 2; }
[ -z "$log" ] || [ -z "$url" ] || die "a log or --lcm-url, not both"
[ -z "$speed" ] || [[ "$speed" =~ ^[0-9]*\.?[0-9]+([eE][-+]?[0-9]+)?$ ]] \
  || die "--speed needs a positive number, not '$speed'"
[ -z "$log" ] || [ -r "$log" ] || die "cannot read the log '$log'"

here="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)"
types="${FSI_LCMTYPES_JAR:-$here/../share/fsi/java/fsi_lcmtypes.jar}"
[ -f "$LCM_JAR" ] || die "$LCM_JAR missing: install Debian's liblcm-java (launch/setup.sh does)"
[ -f "$CHART_JAR" ] || die "$CHART_JAR missing: install Debian's libjchart2d-java (launch/setup.sh does)"
[ -f "$types" ] || die "no message types for lcm-spy ($types): they are built when liblcm-java and a JDK are present; rebuild"
command -v java >/dev/null || die "no java: install a JDK (openjdk-17-jdk-headless)"
classpath="$LCM_JAR:$CHART_JAR:$types"
spy=(java -Djava.net.preferIPv4Stack=true -Xmx256m -cp "$classpath" lcm.spy.Spy)

if [ -n "$url" ]; then
  exec "${spy[@]}" --lcm-url="$url"
fi

# Inside a new user and network namespace: loopback up with the multicast route on
# it, lcm-spy, then the player; closing lcm-spy ends the player. The system test sets
# FSI_TEST_SPY_RECORDER=fsi-record and FSI_TEST_SPY_RECORD=FILE to put the recorder in
# lcm-spy's place (it has no display) and checks that what the player sent in the
# namespace is the log.
export FSI_SPY_LOG="$log" FSI_SPY_SPEED="$speed" FSI_SPY_URL="$PRIVATE_URL" FSI_SPY_CP="$classpath"
export FSI_TEST_SPY_RECORD="${FSI_TEST_SPY_RECORD:-}" FSI_TEST_SPY_RECORDER="${FSI_TEST_SPY_RECORDER:-}"
exec unshare -rn bash -c '
  set -euo pipefail
  ip link set lo up
  ip route add 224.0.0.0/4 dev lo
  viewer="" player=""
  trap '"'"'kill $viewer $player 2>/dev/null || true'"'"' EXIT
  trap "exit 143" TERM INT HUP
  if [ -n "$FSI_TEST_SPY_RECORD" ]; then
    "$FSI_TEST_SPY_RECORDER" "$FSI_SPY_URL" "$FSI_TEST_SPY_RECORD" &
  else
    java -Djava.net.preferIPv4Stack=true -Xmx256m -cp "$FSI_SPY_CP" lcm.spy.Spy \
      --lcm-url="$FSI_SPY_URL" &
  fi
  viewer=$!
  sleep 2   # lcm-spy subscribes before the first message is played
  if [ -n "$FSI_SPY_SPEED" ]; then
    lcm-logplayer -s "$FSI_SPY_SPEED" -l "$FSI_SPY_URL" "$FSI_SPY_LOG" &
  else
    java -Djava.net.preferIPv4Stack=true -Xmx256m -cp "$FSI_SPY_CP" lcm.logging.LogPlayer \
      --lcm-url="$FSI_SPY_URL" "$FSI_SPY_LOG" &
  fi
  player=$!
  if [ -n "$FSI_TEST_SPY_RECORD" ]; then
    wait "$player"
    sleep 1
    kill -INT "$viewer"
    wait "$viewer" || true
  else
    wait "$viewer" || true
    kill "$player" 2>/dev/null || true
  fi
'
