"""Reads a traffic log written by `fsi run --log-traffic` (OUT/traffic.lcmlog).

The log is LCM's event-log format: a sequence of events, each

    sync word 0xEDA1DA01 (uint32), event number (int64), timestamp [us] (int64),
    channel length (int32), data length (int32), channel, data

all big-endian. The format is read directly (Debian has no Python binding of LCM);
each message is decoded with the Python types that lcm-gen generates from
proto/fsi.lcm at build time (package `fsi`, in build/python beside this module, and
installed with it to PREFIX/share/fsi/python).

    import fsi_traffic
    for event in fsi_traffic.read_events("out/demo/traffic.lcmlog"):
        m = event.message        # fsi.step_t, fsi.solid_state_t, ... or None
        print(event.channel, m.header.window, m.header.iteration)

`python3 fsi_traffic.py LOG` prints one line per window and iteration: the channels
seen and their message counts (a short form of `fsi inspect LOG`).
"""

import collections
import struct
import sys

import fsi

SYNC_WORD = 0xEDA1DA01
_EVENT_HEAD = struct.Struct(">Iqqii")

# Channel FSI_SOLID_STATE carries fsi.solid_state_t, and so on (core/protocol.c).
MESSAGE_TYPES = {
    "FSI_" + name.upper(): getattr(fsi, name + "_t")
    for name in ("register", "welcome", "step", "solid_state", "fluid_load", "done",
                 "resend", "heartbeat", "abort")
}

Event = collections.namedtuple("Event", "number timestamp channel data message")


class TrafficLogError(ValueError):
    """The file is not an LCM event log, or ends inside an event."""


def read_raw_events(path):
    """Yields (event number, timestamp [us], channel, data bytes) of every event."""
    with open(path, "rb") as f:
        offset = 0
        while True:
            head = f.read(_EVENT_HEAD.size)
            if not head:
                return
            if len(head) < _EVENT_HEAD.size:
                raise TrafficLogError(f"{path}: ends inside the event at byte {offset}")
            sync, number, timestamp, channel_len, data_len = _EVENT_HEAD.unpack(head)
            if sync != SYNC_WORD or channel_len < 0 or data_len < 0:
                raise TrafficLogError(f"{path}: no LCM event at byte {offset}")
            channel = f.read(channel_len)
            data = f.read(data_len)
            if len(channel) < channel_len or len(data) < data_len:
                raise TrafficLogError(f"{path}: ends inside event {number}")
            offset += _EVENT_HEAD.size + channel_len + data_len
            yield number, timestamp, channel.decode("utf-8", "replace"), data


def decode(channel, data):
    """The message of one event as its generated type, or None for a channel that is
    not the protocol's or data that does not decode (a wrong type fingerprint)."""
    kind = MESSAGE_TYPES.get(channel)
    if kind is None:
        return None
    try:
        return kind.decode(data)
    except (ValueError, struct.error):
        return None


def read_events(path):
    """Yields every event of the log as an Event whose message is decoded."""
    for number, timestamp, channel, data in read_raw_events(path):
        yield Event(number, timestamp, channel, data, decode(channel, data))


def windows(path):
    """{(window, iteration): Counter of channel -> messages} over the decoded
    messages other than heartbeats and resend requests, which `fsi inspect` counts
    apart."""
    lines = collections.defaultdict(collections.Counter)
    for event in read_events(path):
        m = event.message
        if m is None or event.channel in ("FSI_HEARTBEAT", "FSI_RESEND"):
            continue
        lines[(m.header.window, m.header.iteration)][event.channel] += 1
    return dict(lines)


def main(argv):
    if len(argv) != 2:
        print("usage: fsi_traffic.py LOG", file=sys.stderr)
        return 2
    try:
        lines = windows(argv[1])
    except (OSError, TrafficLogError) as e:
        print(f"fsi_traffic: {e}", file=sys.stderr)
        return 2
    for (window, iteration), channels in sorted(lines.items()):
        for channel, count in sorted(channels.items()):
            print(f"{window} {iteration} {channel} {count}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
