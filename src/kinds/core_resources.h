#pragma once
// Every core kind's hardware, one include per kind (as registry.h lists the kinds): each kind's
// folder declares `CoreResources coreResources(const Kind::Config&)`, which
// sim/rtu_resources.h finds by the chosen kind's Config. A new kind adds its line here.

#include "kinds/bih/bih_resources.h"
#include "kinds/bvh/bvh_resources.h"
#include "kinds/kd/kd_resources.h"
#include "kinds/svo/svo_resources.h"
