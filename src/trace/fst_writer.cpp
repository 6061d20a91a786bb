// FST, GTKWave's compressed trace format, through the writer GTKWave and Verilator ship
// (fstapi.c, built from Debian's verilator package: modules/CMakeLists.txt). Variables with
// named values get an enum table, so GTKWave shows the names (IDLE, INIT, ...) without a filter.

#include <map>
#include <stdexcept>

#include "fstapi.h"
#include "trace/trace_writer.h"

namespace rtu {
namespace {

class FstWriter : public TraceWriter {
 public:
  explicit FstWriter(const std::string& path) : fst_(fstWriterCreate(path.c_str(), 1)) {
    if (!fst_) throw std::runtime_error("cannot write trace file " + path);
    fstWriterSetTimescale(fst_, -12);  // 1 ps
    fstWriterSetPackType(fst_, FST_WR_PT_LZ4);
  }
  ~FstWriter() override {
    if (fst_) fstWriterClose(fst_);
  }
  void enterScope(const std::string& name) override {
    fstWriterSetScope(fst_, FST_ST_VCD_MODULE, name.c_str(), nullptr);
  }
  void leaveScope() override { fstWriterSetUpscope(fst_); }
  void variable(size_t index, const TraceVariable& variable) override {
    if (!variable.valueNames.empty()) fstWriterEmitEnumTableRef(fst_, enumTable(variable));
    if (variables_.size() <= index) variables_.resize(index + 1);
    const fstHandle handle =
        fstWriterCreateVar(fst_, FST_VT_VCD_WIRE, FST_VD_IMPLICIT,
                           static_cast<uint32_t>(variable.width), variable.name.c_str(), 0);
    variables_[index] = {variable.width, handle};
  }
  void endDeclarations() override {}
  void beginInitial(uint64_t timePs) override { time(timePs); }
  void endInitial() override {}
  void time(uint64_t timePs) override { fstWriterEmitTimeChange(fst_, timePs); }
  void value(size_t index, bool known, uint64_t value) override {
    const auto [width, handle] = variables_[index];
    const std::string text = known ? bitString(value, width)
                                   : std::string(static_cast<size_t>(width), 'x');
    fstWriterEmitValueChange(fst_, handle, text.c_str());
  }
  void close() override {
    fstWriterClose(fst_);
    fst_ = nullptr;
  }

 private:
  // One table per distinct list of names (all cores share one).
  fstEnumHandle enumTable(const TraceVariable& variable) {
    auto [entry, added] = enums_.try_emplace(variable.valueNames, 0);
    if (!added) return entry->second;
    std::vector<std::string> values;
    std::vector<const char*> names, valueTexts;
    for (size_t v = 0; v < variable.valueNames.size(); ++v)
      values.push_back(bitString(v, variable.width));
    for (size_t v = 0; v < values.size(); ++v) {
      names.push_back(variable.valueNames[v].c_str());
      valueTexts.push_back(values[v].c_str());
    }
    const std::string tableName = variable.name + "_" + std::to_string(enums_.size());
    entry->second =
        fstWriterCreateEnumTable(fst_, tableName.c_str(), static_cast<uint32_t>(names.size()),
                                 static_cast<unsigned>(variable.width), names.data(),
                                 valueTexts.data());
    return entry->second;
  }

  void* fst_;
  struct Variable {
    int width;
    fstHandle handle;
  };
  std::vector<Variable> variables_;
  std::map<std::vector<std::string>, fstEnumHandle> enums_;
};

}  // namespace

std::unique_ptr<TraceWriter> openFstWriter(const std::string& path) {
  return std::make_unique<FstWriter>(path);
}

}  // namespace rtu
