#include "raypipe/raypipe_cache.h"

namespace rtu {

// R1 COMMON/defines.sv: T_LINE_W 384 (8 nodes of 48 bits, T_BO_W 3), L_LINE_W 256 (16 list
// entries of 16 bits, L_BO_W 4), I_LINE_W 288 (one triangle, I_BO_W 0); bytes = LINE_W / 8.
RaypipeCacheGeometry raypipeCacheGeometry(RaypipeCacheId id, const RaypipeCacheSettings& s) {
  switch (id) {
    case RaypipeCacheId::Icache: return {1, 36, static_cast<uint32_t>(s.icacheLines)};
    case RaypipeCacheId::Lcache: return {16, 32, static_cast<uint32_t>(s.lcacheLines)};
    case RaypipeCacheId::Tcache:
    case RaypipeCacheId::Tcache1: break;
  }
  return {8, 48, static_cast<uint32_t>(s.tcacheLines)};
}

}  // namespace rtu
