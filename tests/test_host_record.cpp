// The host records of the kind registry (kinds/host_record.h): every kind's own record once, then
// the world-space ray; a kind's set-up reached through the overload for a record's type, and a
// record the kind has none for refused with a message naming both.
#include <catch2/catch.hpp>

#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#include "kinds/registry.h"
#include "toy_kind.h"

namespace rtu {
namespace {

// A kind that takes world-space rays only (as the triangle kinds will): its job is the ray's
// model address.
struct RaysOnlyKind {
  static constexpr const char* kName = "rays-only";
  using Job = uint32_t;
  class Setup {
   public:
    JobSetUp<Job> setUp(const RayRecord& ray) { return {ray.modelAddress, ray.id, 7, 0}; }
  };
};

}  // namespace

TEST_CASE("Host records: each kind's own record once, in the kinds' order, then the ray",
          "[kinds]") {
  static_assert(std::is_same_v<HostRecord, std::variant<TValueRecord, RayRecord>>);
  static_assert(std::is_same_v<HostRecordOf<SvoKind, ToyKind, SvoKind>,
                               std::variant<TValueRecord, uint32_t, RayRecord>>);
  static_assert(std::is_same_v<HostRecordOf<RaysOnlyKind>, std::variant<RayRecord>>);
  CHECK(HostRecord{RayRecord{}}.index() == 1);  // the host buffers' t-value records come first
}

TEST_CASE("Host records: a kind's set-up takes the overload for the record's type", "[kinds]") {
  RaysOnlyKind::Setup setup;
  RayRecord ray;
  ray.id = 5;
  ray.modelAddress = 40;
  const JobSetUp<uint32_t> set = setUpHostRecord<RaysOnlyKind>(setup, HostRecord{ray});
  CHECK(set.job == 40);
  CHECK(set.idWord == 5);
  CHECK(set.latency == 7);
}

TEST_CASE("Host records: a record the kind takes no overload for is refused, naming both",
          "[kinds]") {
  RaysOnlyKind::Setup setup;
  CHECK_THROWS_AS(setUpHostRecord<RaysOnlyKind>(setup, HostRecord{TValueRecord{}}),
                  std::invalid_argument);
  CHECK_THROWS_WITH(setUpHostRecord<RaysOnlyKind>(setup, HostRecord{TValueRecord{}}),
                    "the rays-only core takes no t-value records");
}

TEST_CASE("Host records: a run's records are checked against its kind before it starts",
          "[kinds]") {
  std::vector<HostRecord> records{RayRecord{}, RayRecord{}};
  CHECK_NOTHROW(checkTakesRecords<RaysOnlyKind>(records));
  records.push_back(TValueRecord{});
  CHECK_THROWS_WITH(checkTakesRecords<RaysOnlyKind>(records),
                    "the rays-only core takes no t-value records");
  CHECK_NOTHROW(checkCoreTakes(SvoKind::kName, records));
}

TEST_CASE("Host records: the registry's set-up converts with the chosen kind's settings",
          "[kinds]") {
  TValueRecord record;
  record.t0Bits = {floatBits(0.5f), floatBits(0.5f), floatBits(0.5f)};
  record.t1Bits = {floatBits(2.0f), floatBits(2.0f), floatBits(2.0f)};
  const JobManagerTiming timing{3, 4, 5};
  CoreKindConfigs configs;
  CoreKinds::configOf<SvoKind>(configs).format = FixedFormat{28, 12};
  const CoreKindJobSetUp set =
      makeCoreJobSetup(SvoKind::kName, WordMemory(), timing, configs)(HostRecord{record});
  CHECK(set.latency == 3);
  CHECK(set.headerFetch == 0);
  const SvoJob& job = std::get<SvoJob>(set.job);
  CHECK(job.t0[0] == 2048);  // 0.5 with 12 fraction bits
  CHECK(job.t1[2] == 8192);
}

}  // namespace rtu
