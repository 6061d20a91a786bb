#!/usr/bin/env python3
"""Checks a --timeline file (Chrome trace-event JSON) against what the run reports elsewhere.

usage: timeline_check.py TIMELINE STATS_JSON GOLDEN_OUT [--cached]

- one ray slice per ray, named after its job, the slices of a core never overlapping, each OUT
  and BLOCKED slice inside one of them;
- per ray: its cycles outside OUT and BLOCKED equal the golden model's cost of that job (the
  untimed model's output buffer, word 6 of each 8-word record);
- per core: ray slices, BLOCKED cycles and OUT cycles equal the statistics' jobs, blocked and
  handover cycles; BLOCKED spans exist exactly when the memory is cached;
- the scheduler-wait counter integrates to the statistics' waits (sum of the wait histogram);
- the counters return to zero and never go negative.
"""
import collections
import json
import struct
import sys


def fail(message):
    print("timeline_check: " + message)
    sys.exit(1)


def golden_costs(path):
    data = open(path, "rb").read()
    words = struct.unpack("<%dI" % (len(data) // 4), data)
    return {words[i] & 0x0FFFFFFF: words[i + 6] for i in range(0, len(words), 8)}


def counter_area(samples, end):
    """Integral over cycles of a step counter given (cycle, value) samples."""
    area = 0
    for (cycle, value), (next_cycle, _) in zip(samples, samples[1:] + [(end, 0)]):
        area += value * (next_cycle - cycle)
    return area


def main():
    timeline, stats_path, golden_path = sys.argv[1:4]
    cached = "--cached" in sys.argv
    events = json.load(open(timeline))["traceEvents"]
    stats = json.load(open(stats_path))["statistics"]
    costs = golden_costs(golden_path)

    mhz = stats["clock_mhz"]
    for e in events:  # time stamps in microseconds -> cycles
        if "ts" in e:
            e["cycle"] = round(e["ts"] * mhz)
        if "dur" in e:
            e["cycles"] = round(e["dur"] * mhz)
    names = {e["tid"]: e["args"]["name"] for e in events if e["name"] == "thread_name"}
    slices = [e for e in events if e["ph"] == "X"]
    rays = {int(e["name"].split()[1]): e for e in slices if e["name"].startswith("ray ")}
    if len(rays) != stats["rays"] or sorted(rays) != list(range(stats["rays"])):
        fail("%d ray slices for %d rays" % (len(rays), stats["rays"]))

    per_core = collections.defaultdict(list)
    for ray, e in rays.items():
        per_core[e["tid"]].append((e["cycle"], e["cycle"] + e["cycles"], ray))
    for tid, spans in per_core.items():
        spans.sort()
        if any(b[0] < a[1] for a, b in zip(spans, spans[1:])):
            fail("ray slices overlap on " + names[tid])

    inner = collections.defaultdict(lambda: collections.Counter())
    for e in slices:
        if e["name"] in ("OUT", "BLOCKED"):
            owner = [ray for start, end, ray in per_core[e["tid"]]
                     if start <= e["cycle"] and e["cycle"] + e["cycles"] <= end]
            if len(owner) != 1:
                fail("%s at cycle %d outside a ray slice" % (e["name"], e["cycle"]))
            inner[owner[0]][e["name"]] += e["cycles"]
    for ray, e in rays.items():
        busy = e["cycles"] - inner[ray]["OUT"] - inner[ray]["BLOCKED"]
        if busy != costs[ray]:
            fail("ray %d: %d cycles outside OUT and BLOCKED, golden cost %d" % (ray, busy, costs[ray]))

    for core in stats["cores"]:
        tid = core["core"] + 1
        mine = [e for e in slices if e["tid"] == tid]
        got = {"jobs": sum(e["name"].startswith("ray ") for e in mine),
               "blocked": sum(e["cycles"] for e in mine if e["name"] == "BLOCKED"),
               "handover": sum(e["cycles"] for e in mine if e["name"] == "OUT")}
        for key, value in got.items():
            if value != core[key]:
                fail("%s: %s %d in the timeline, %d in the statistics" % (names[tid], key, value, core[key]))
    blocked = sum(e["name"] == "BLOCKED" for e in slices)
    if (blocked > 0) != cached:
        fail("%d BLOCKED spans in a run with %s memory" % (blocked, "cached" if cached else "ideal"))

    counters = collections.defaultdict(list)
    for e in events:
        if e["ph"] == "C":
            counters[e["name"]].append((e["cycle"], list(e["args"].values())[0]))
    end = stats["total_cycles"]
    waits = sum(wait * jobs for wait, jobs in enumerate(stats["scheduler"]["wait_histogram"]))
    if counter_area(counters["scheduler wait"], end) != waits:
        fail("scheduler wait counter covers %d cycles, the statistics %d"
             % (counter_area(counters["scheduler wait"], end), waits))
    for name, samples in counters.items():
        if samples[-1][1] != 0 or min(v for _, v in samples) < 0:
            fail("counter %s ends at %d or goes negative" % (name, samples[-1][1]))
    print("timeline_check: %d rays, %d BLOCKED spans, %d counter samples: ok"
          % (len(rays), blocked, sum(map(len, counters.values()))))


main()
