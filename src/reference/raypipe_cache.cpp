// The per-cycle reference of seed 001's ray pipe: the caches and the memory request arbiter
// (raypipe_cache.h).
#include "reference/raypipe_cache.h"

#include <cmath>

namespace rtu {
namespace raypipe_ref {
namespace {

// R1 cache.sv: the reissue FIFO (RIF) holds 5 (RIF_DEPTH = DEPTH + 3) and its buffer DEPTH + 1
// more (the items in the pipe when a new one stalls); a new item stalls while the RIF is full. Both
// are one FIFO here (docs/raypipe.md), its buffer sized by the configured read latency; the miss
// request FIFO (MRF_DEPTH = RIF_DEPTH + DEPTH + 1) holds at most one line per waiting item.
constexpr int kRifDepth = 5;
int reissueDepth(const RaypipeConfig& c) { return kRifDepth + c.latency.memoryRead + 1; }

}  // namespace

void DramArbiter::tick(int64_t now, const std::array<bool, kRaypipeDramPorts>& asking,
                       const std::array<uint32_t, kRaypipeDramPorts>& bytes) {
  if (busy_) {
    if (done_ != now) return;
    busy_ = false;
    current_ = (current_ + 1) % kRaypipeDramPorts;
    return;
  }
  if (!asking[static_cast<size_t>(current_)]) {
    current_ = (current_ + 1) % kRaypipeDramPorts;
    return;
  }
  const uint32_t b = bytes[static_cast<size_t>(current_)];
  const auto transfer = static_cast<int64_t>(std::ceil(b / settings_.dramBytesPerCycle));
  busy_ = true;
  port_ = current_;
  done_ = now + settings_.dramLatency + transfer;
  ++counts_.reads;
  counts_.bytes += b;
  counts_.busyCycles += transfer;
}

CacheRead::CacheRead(const std::string& name, RaypipeCacheId id, const RaypipeConfig& c)
    : pipe(c.latency.memoryRead),
      fifo(name, c.fifo.memoryOut),
      id_(id),
      setAssociative_(c.cache == RaypipeCacheKind::SetAssociative),
      geometry_(raypipeCacheGeometry(id, c.caches)),
      tags_(geometry_.sets),
      reissue_(name + "_reissue", reissueDepth(c)),
      requests_(name + "_requests", reissueDepth(c)) {
  counts_.cache = name;
}

uint64_t CacheRead::lineOf(const Flit& f) const {
  switch (id_) {
    case RaypipeCacheId::Icache: return geometry_.lineOf(f.tri);
    case RaypipeCacheId::Lcache: return geometry_.lineOf(f.lindex);
    default: return geometry_.lineOf(f.node);
  }
}

bool CacheRead::cycle(int64_t now, bool dsStall, const DramArbiter& dram, int64_t cyclesFromReset) {
  const bool pipeStall = pipe.usStall(dsStall, fifo.numLeft());
  if (!setAssociative_) return pipeStall;
  bool reissued = false;
  if (!reissue_.empty() && !pipeStall) {
    const Reissue& head = reissue_.front();
    if (!head.wait || fromMhValid(now, dram)) {
      Flit f = head.flit;
      if (head.wait) {
        tags_.fill(lineOf(f), raypipeWayChoice(now, cyclesFromReset));
        f.cacheHit = true;  // cache.sv's way*_we2: the written line, whatever the tags read
        taken_ = true;
        ++counts_.fills;
        requests_.pop();
      } else {
        f.cacheHit = tags_.holds(lineOf(f));
      }
      ++counts_.reissues;
      reissue_.pop();
      pipe.accept(f);
      reissued = true;
    }
  }
  return reissued || reissue_.size() >= kRifDepth || pipeStall;
}

bool CacheRead::exitHit(int64_t now, Flit& out) {
  if (!pipe.outValid(now)) return false;
  const Flit& f = pipe.out(now);
  if (!setAssociative_) {
    out = f;
    return true;
  }
  if (f.cacheHit) {
    ++counts_.hits;
    out = f;
    return true;
  }
  ++counts_.misses;
  const uint64_t line = lineOf(f);
  const bool ask = !requests_.contains(line);
  if (ask) requests_.push(now, line);
  reissue_.push(now, Reissue{f, ask});
  return false;
}

void CacheRead::accept(const Flit& f) {
  Flit item = f;
  item.cacheHit = setAssociative_ && tags_.holds(lineOf(f));
  pipe.accept(item);
}

void CacheRead::tick(int64_t now, const DramArbiter& dram) {
  if (setAssociative_) {
    const bool delivered = fromMhValid(now, dram);
    switch (state_) {
      case Mh::Idle:
        if (!requests_.empty()) state_ = Mh::Request;
        break;
      case Mh::Request: state_ = Mh::Wait; break;
      case Mh::Wait:
      case Mh::Hold:
        if (delivered) state_ = taken_ ? Mh::Idle : Mh::Hold;
        break;
    }
    taken_ = false;
    reissue_.tick(now);
    requests_.tick(now);
  }
  pipe.tick(now);
  fifo.tick(now);
}

}  // namespace raypipe_ref
}  // namespace rtu
