#pragma once
// What travels through the timed model's channels and what it keeps per ray id. A RayToken is the
// union of the RTL's packed structs on the pipe's channels (tarb_t, leaf_info_t, trav_to_ss_t,
// int_to_list_t, ...); a RayRecord is what R1's ray-id-indexed block RAMs hold of one ray (the
// raystores, the short stack's rows and restart record, the list unit's record, the shader's pixel
// id) with the ray's counters.

#include <cstdint>

#include "kinds/kd/kd_traversal.h"
#include "kinds/kd/kd_units.h"
#include "kinds/kd/trayracer_scene.h"

namespace rtu {
namespace raypipe_timed {

struct RayToken {
  uint32_t ray = 0;    // rayID
  uint32_t index = 0;  // the pixel's place in the PRG's order
  uint32_t node = 0;   // tarb_t
  float tMin = 0, tMax = 0;
  uint32_t wptr = 0, num = 0;                                                  // ss_wptr, ss_num
  bool search = false;                                                         // restnode_search
  bool pushReq = false, popReq = false, restReq = false, maxsceneReq = false;  // trav_to_ss_t
  bool last = false, isHit = false, boxMiss = false, miss = false;
  bool cacheHit = false;  // the cache's lookup as the token entered it (timed_cache.h)
  uint32_t pushNode = 0;
  uint32_t lindex = 0, lnum = 0, tri = 0;  // leaf_info_t, the list entry
  TrayRacerNode nodeData;                  // tcache's read
  KdPlaneTest plane;                       // TRAV's math
  KdTriangleHit found;                     // INT's
  float t = 0, u = 0, v = 0;               // the list unit's answer
};

// What a traced FIFO (pipe_trace.h) shows at its head: the ray id, or before the shader gives one
// (the PRG's FIFO) the pixel's place in the issue order.
inline uint64_t traceHead(const RayToken& t, bool pixels) { return pixels ? t.index : t.ray; }

struct StackRow {
  uint32_t node = 0;
  float tMax = 0;
};

struct RayRecord {
  bool busy = false;
  uint32_t index = 0;
  uint32_t restNode = 0;
  float tMaxScene = 0;
  bool hitCur = false;
  float tCur = 0, uCur = 0, vCur = 0;
  uint32_t triCur = 0;
  float leafMax = 0;
  KdRayCounts counts;
};

}  // namespace raypipe_timed
}  // namespace rtu
