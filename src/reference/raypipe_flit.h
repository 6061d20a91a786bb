#pragma once
// The per-cycle reference of seed 001's ray pipe: what every channel carries, the union of the
// RTL's packed structs (tarb_t, leaf_info_t, trav_to_ss_t, int_to_list_t, ...).

#include <cstdint>

#include "kinds/kd/kd_traversal.h"
#include "kinds/kd/kd_units.h"
#include "kinds/kd/trayracer_scene.h"

namespace rtu {
namespace raypipe_ref {

struct Flit {
  uint32_t ray = 0;    // rayID
  uint32_t index = 0;  // the pixel's place in the PRG's order
  // tarb_t
  uint32_t node = 0;
  float tMin = 0, tMax = 0;
  bool search = false;         // restnode_search
  uint32_t wptr = 0, num = 0;  // ss_wptr, ss_num
  TrayRacerNode nodeData;      // tcache's read
  KdPlaneTest plane;           // trav_math's results
  // trav_to_ss_t
  bool pushReq = false, popReq = false, restReq = false, maxsceneReq = false;
  uint32_t pushNode = 0;
  // leaf_info_t, lcache's and INT's
  uint32_t lindex = 0, lnum = 0, tri = 0;
  bool last = false;
  KdTriangleHit found;
  // the list unit's decision and what reaches the shader
  bool isHit = false, boxMiss = false, miss = false;
  bool cacheHit = false;  // the cache's lookup as the item entered it (raypipe_cache.h)
  float t = 0, u = 0, v = 0;
};

}  // namespace raypipe_ref
}  // namespace rtu
