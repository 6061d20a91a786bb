// FST, GTKWave's compressed trace format, through the writer GTKWave and Verilator ship
// (fstapi.c, built from Debian's verilator package: modules/CMakeLists.txt). Variables with
// named values get an enum table, so GTKWave shows the names (IDLE, INIT, ...) without a filter.

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include "base/output_file.h"
#include "fstapi.h"
#include "trace/trace_writer.h"

namespace rtu {
namespace {

class FstWriter : public TraceWriter {
 public:
  // The writer writes a scratch file in the temporary folder, copied into the output when
  // complete: it maps a file of its own beside the trace (NAME.hier), which on a full disk
  // killed the process with SIGBUS, and it checks none of its writes.
  FstWriter(const std::string& path, TraceTimeUnit unit) : file_(path), scratch_(scratchPath()) {
    fst_ = fstWriterCreate(scratch_.c_str(), 1);
    if (!fst_) file_.fail("the FST writer cannot open '" + scratch_ + "'");
    fstWriterSetTimescale(fst_, unit.exponent);
    fstWriterSetPackType(fst_, FST_WR_PT_LZ4);
  }
  ~FstWriter() override {
    if (fst_) fstWriterClose(fst_);
    ::unlink(scratch_.c_str());
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
  void beginInitial(uint64_t time) override { this->time(time); }
  void endInitial() override {}
  void time(uint64_t time) override {
    fstWriterEmitTimeChange(fst_, time);
    endTime_ = time;
  }
  void value(size_t index, bool known, uint64_t value) override {
    const auto [width, handle] = variables_[index];
    const std::string text = known ? bitString(value, width)
                                   : std::string(static_cast<size_t>(width), 'x');
    fstWriterEmitValueChange(fst_, handle, text.c_str());
  }
  void close() override {
    fstWriterClose(fst_);
    fst_ = nullptr;
    checkWritten();
    std::ifstream written(scratch_, std::ios::binary);
    if (!written.is_open()) file_.fail("cannot read the FST writer's file '" + scratch_ + "'");
    file_.stream() << written.rdbuf();
    file_.commit();
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

  static std::string scratchPath() {
    std::string path = (std::filesystem::temp_directory_path() / "rtusim-XXXXXX.fst").string();
    const int fd = ::mkstemps(path.data(), 4);
    if (fd < 0)
      throw std::runtime_error("cannot create a scratch file for an FST trace in " + path);
    ::close(fd);
    return path;
  }

  // The FST writer reports no write error: its file is read back and must hold every variable
  // and the last time written (a full disk leaves it short).
  void checkWritten() {
    void* reader = fstReaderOpen(scratch_.c_str());
    if (!reader)
      file_.fail("the FST writer left an unreadable file '" + scratch_ +
                 "' (temporary folder full?)");
    const bool whole = fstReaderGetVarCount(reader) == variables_.size() &&
                       fstReaderGetEndTime(reader) == endTime_;
    fstReaderClose(reader);
    if (!whole)
      file_.fail("the FST writer left an incomplete file '" + scratch_ +
                 "' (temporary folder full?)");
  }

  OutputFile file_;
  std::string scratch_;
  void* fst_ = nullptr;
  uint64_t endTime_ = 0;
  struct Variable {
    int width;
    fstHandle handle;
  };
  std::vector<Variable> variables_;
  std::map<std::vector<std::string>, fstEnumHandle> enums_;
};

}  // namespace

std::unique_ptr<TraceWriter> openFstWriter(const std::string& path, TraceTimeUnit unit) {
  return std::make_unique<FstWriter>(path, unit);
}

}  // namespace rtu
