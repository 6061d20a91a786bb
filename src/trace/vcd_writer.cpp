// Value change dump (IEEE 1364), the text format every waveform viewer reads. Named values are
// written as numbers; the save file names them through a translate filter (gtkw_save_file.h).

#include <optional>
#include <stdexcept>

#include "base/counting_stream.h"
#include "base/output_file.h"
#include "trace/trace_writer.h"

namespace rtu {
namespace {

// VCD identifier codes: base-94 numbers in the printable characters '!' to '~'.
std::string identifierCode(size_t index) {
  std::string code;
  do {
    code += static_cast<char>('!' + index % 94);
    index /= 94;
  } while (index > 0);
  return code;
}

class VcdWriter : public TraceWriter {
 public:
  // `counter` non-null: writes into it instead of the file at `path`, to count the bytes.
  VcdWriter(const std::string& path, CountingStream* counter, TraceTimeUnit unit)
      : counter_(counter) {
    if (!counter_) file_.emplace(path);
    out() << "$timescale " << unit.vcdTimescale() << " $end\n";
  }
  uint64_t bytes() const override { return counter_ ? counter_->count() : 0; }
  void enterScope(const std::string& name) override {
    out() << "$scope module " << name << " $end\n";
  }
  void leaveScope() override { out() << "$upscope $end\n"; }
  void variable(size_t index, const TraceVariable& variable) override {
    if (variables_.size() <= index) variables_.resize(index + 1);
    variables_[index] = {variable.width, identifierCode(index)};
    out() << "$var wire " << variable.width << ' ' << variables_[index].code << ' ' << variable.name
          << " $end\n";
  }
  void endDeclarations() override { out() << "$enddefinitions $end\n"; }
  void beginInitial(uint64_t time) override { out() << '#' << time << "\n$dumpvars\n"; }
  void endInitial() override { out() << "$end\n"; }
  void time(uint64_t time) override { out() << '#' << time << '\n'; }
  void value(size_t index, bool known, uint64_t value) override {
    const auto& [width, code] = variables_[index];
    if (width == 1)
      out() << (known ? (value ? '1' : '0') : 'x') << code << '\n';
    else
      out() << 'b' << (known ? bitString(value, width) : std::string("x")) << ' ' << code << '\n';
  }
  void close() override {
    if (file_) file_->commit();
  }

 private:
  std::ostream& out() { return counter_ ? static_cast<std::ostream&>(*counter_) : file_->stream(); }

  CountingStream* counter_;
  std::optional<OutputFile> file_;
  struct Variable {
    int width;
    std::string code;
  };
  std::vector<Variable> variables_;
};

}  // namespace

std::unique_ptr<TraceWriter> openVcdWriter(const std::string& path, TraceTimeUnit unit) {
  return std::make_unique<VcdWriter>(path, nullptr, unit);
}

std::unique_ptr<TraceWriter> openVcdCounter(CountingStream& counter, TraceTimeUnit unit) {
  return std::make_unique<VcdWriter>("(counted)", &counter, unit);
}

}  // namespace rtu
