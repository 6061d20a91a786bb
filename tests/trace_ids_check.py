#!/usr/bin/env python3
"""Follows every ray through a trace by the ids its channels carry (signal class ids) and checks
them against the run: each ray crosses the job manager's input, the scheduler's input, exactly
one core's input and the same core's output, and the host's output, once each, in that order of
cycles (the scheduler's input and the core's input in the same cycle: its dispatch); and the
host receives the rays in the order of the output buffer.
Usage: trace_ids_check.py changes.txt out.bin
changes.txt is vcd_normalise.py's "cycle signal value" form of the trace."""
import re
import struct
import sys


def load(path):
    levels = {}
    for line in open(path):
        cycle, name, value = line.split()
        levels.setdefault(name, []).append((int(cycle), None if value == "x" else int(value)))
    return levels


def transfers(levels, channel):
    """(cycle, ray) of each cycle in which channel.valid and channel.ready are both high."""
    events = sorted([(c, "valid", v) for c, v in levels[channel + ".valid"]] +
                    [(c, "ready", v) for c, v in levels[channel + ".ready"]] +
                    [(c, "ray", v) for c, v in levels[channel + ".ray"]])
    state, since, out = {"valid": 0, "ready": 0, "ray": None}, 0, []
    for cycle, which, value in events + [(10**12, "valid", 0)]:
        if cycle > since and state["valid"] and state["ready"]:
            assert state["ray"] is not None, "%s: a transfer in cycle %d without a ray id" % (channel, since)
            out.extend((c, state["ray"]) for c in range(since, cycle))
        state[which], since = value, cycle
    return out


def once(channel_transfers, channel, rays):
    by_ray = {}
    for cycle, ray in channel_transfers:
        assert ray not in by_ray, "%s: ray %d crosses twice" % (channel, ray)
        by_ray[ray] = cycle
    assert sorted(by_ray) == list(range(rays)), "%s: carries %d of %d rays" % (channel, len(by_ray), rays)
    return by_ray


def main():
    levels = load(sys.argv[1])
    data = open(sys.argv[2], "rb").read()
    words = struct.unpack("<%dI" % (len(data) // 4), data)
    buffer_order = [words[i] & 0x0FFFFFFF for i in range(0, len(words), 8)]
    rays = len(buffer_order)

    entered = once(transfers(levels, "rtu.job_manager.in"), "job manager in", rays)
    pending = once(transfers(levels, "rtu.scheduler.in"), "scheduler in", rays)
    host = transfers(levels, "rtu.result_manager.out")
    received = once(host, "host out", rays)
    assert [ray for _, ray in host] == buffer_order, "the host's ray ids are not the output buffer's order"

    cores = sorted({m.group(1) for name in levels for m in [re.match(r"rtu\.(core_\d+)\.in\.ray$", name)] if m})
    dispatched, finished = {}, {}
    for core in cores:
        for direction, seen in (("in", dispatched), ("out", finished)):
            for cycle, ray in transfers(levels, "rtu.%s.%s" % (core, direction)):
                assert ray not in seen, "ray %d enters or leaves a core twice" % ray
                seen[ray] = (core, cycle)
    assert sorted(dispatched) == list(range(rays)) and sorted(finished) == list(range(rays))
    for ray in range(rays):
        core_in, dispatch = dispatched[ray]
        core_out, handover = finished[ray]
        assert core_in == core_out, "ray %d enters %s and leaves %s" % (ray, core_in, core_out)
        assert entered[ray] < pending[ray] == dispatch < handover < received[ray], \
            "ray %d: cycles %d, %d, %d, %d, %d out of order" % (
                ray, entered[ray], pending[ray], dispatch, handover, received[ray])
    print("trace_ids_check: %d rays followed through %d cores" % (rays, len(cores)))


main()
