#include "sim/raypipe/timed_cache.h"

#include <algorithm>

namespace rtu {
namespace raypipe_timed {
namespace {

constexpr int kRifDepth = 5;  // cache.sv's RIF_DEPTH: new items stall while it holds as many

}  // namespace

TimedCache::TimedCache(const std::string& name, RaypipeCacheId id, const RaypipeConfig& c,
                       DramArbiter& dram)
    : read(name, c.latency.memoryRead, c.fifo.memoryOut),
      id_(id),
      setAssociative_(c.cache == RaypipeCacheKind::SetAssociative),
      geometry_(raypipeCacheGeometry(id, c.caches)),
      tags_(geometry_.sets),
      dram_(dram),
      reissue_(name + "_reissue", kRifDepth + c.latency.memoryRead + 1, kRegister) {
  counts_.cache = name;
}

void TimedCache::bookOn(WakeCalendar& calendar, uint32_t groups) {
  read.pipe.bookOn(calendar, groups);
  read.fifo.bookOn(calendar, groups);
  reissue_.bookOn(calendar, groups);
  if (setAssociative_) dram_.bookOn(calendar, static_cast<int>(id_), groups);
}

uint64_t TimedCache::lineOf(const RayToken& t) const {
  switch (id_) {
    case RaypipeCacheId::Icache: return geometry_.lineOf(t.tri);
    case RaypipeCacheId::Lcache: return geometry_.lineOf(t.lindex);
    default: return geometry_.lineOf(t.node);
  }
}

// The line is in the miss request FIFO at the cycle's start (exists_in_mrf).
bool TimedCache::requested(uint64_t line, int64_t now) const {
  return std::any_of(requests_.begin(), requests_.end(),
                     [&](const auto& r) { return r.first == line && r.second < now; });
}

void TimedCache::ask(int64_t from, int64_t now) {
  asking_ = true;
  dram_.request(static_cast<int>(id_), from, geometry_.lineBytes, now);
}

bool TimedCache::missed(int64_t now) {
  const RayToken t = read.pipe.take(now);
  ++counts_.misses;
  const uint64_t line = lineOf(t);
  const bool wait = !requested(line, now);
  if (wait) {
    if (requests_.empty()) ask(std::max(handlerIdleFrom_, now + 1) + 1, now);
    requests_.emplace_back(line, now);
  }
  reissue_.push(now, Reissue{t, wait});
  return false;
}

// The waiting head took its line's data in `now`: the handler is idle from now + 1 and takes the
// next request from when it is shown.
void TimedCache::deliver(int64_t now) {
  ++counts_.fills;
  dram_.finished(static_cast<int>(id_));
  asking_ = false;
  requests_.pop_front();
  handlerIdleFrom_ = now + 1;
  if (!requests_.empty()) ask(std::max(now + 1, requests_.front().second + 1) + 1, now);
}

bool TimedCache::reissue(int64_t now, bool pipeStall, int64_t cyclesFromReset) {
  dram_.advance(now);
  bool reissued = false;
  if (reissue_.shown(now) && !pipeStall) {
    const Reissue& head = reissue_.front();
    const bool ready = !head.wait || (asking_ && dram_.done(static_cast<int>(id_), now));
    if (ready) {
      Reissue r = reissue_.pop(now);
      if (r.wait) {
        tags_.fill(lineOf(r.token), raypipeWayChoice(now, cyclesFromReset));
        r.token.cacheHit = true;  // cache.sv's way*_we2: the written line, whatever the tags read
        deliver(now);
      } else {
        r.token.cacheHit = tags_.holds(lineOf(r.token));
      }
      ++counts_.reissues;
      read.pipe.accept(now, r.token);
      reissued = true;
    }
  }
  return reissued || reissue_.countAtStart(now) >= kRifDepth || pipeStall;
}

void TimedCache::accept(int64_t now, const RayToken& t) {
  RayToken item = t;
  item.cacheHit = setAssociative_ && tags_.holds(lineOf(t));
  read.pipe.accept(now, item);
}

}  // namespace raypipe_timed
}  // namespace rtu
