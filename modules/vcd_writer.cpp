// Value change dump (IEEE 1364), the text format every waveform viewer reads. Named values are
// shown as numbers; scripts/gtkwave_core_states.txt translates the core state's codes.

#include <fstream>
#include <stdexcept>

#include "trace_writer.h"

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
  explicit VcdWriter(const std::string& path) : path_(path), out_(path) {
    if (!out_) throw std::runtime_error("cannot write trace file " + path);
    out_ << "$timescale 1ps $end\n";
  }
  void enterScope(const std::string& name) override {
    out_ << "$scope module " << name << " $end\n";
  }
  void leaveScope() override { out_ << "$upscope $end\n"; }
  void variable(size_t index, const TraceVariable& variable) override {
    if (variables_.size() <= index) variables_.resize(index + 1);
    variables_[index] = {variable.width, identifierCode(index)};
    out_ << "$var wire " << variable.width << ' ' << variables_[index].code << ' ' << variable.name
         << " $end\n";
  }
  void endDeclarations() override { out_ << "$enddefinitions $end\n"; }
  void beginInitial(uint64_t timePs) override { out_ << '#' << timePs << "\n$dumpvars\n"; }
  void endInitial() override { out_ << "$end\n"; }
  void time(uint64_t timePs) override { out_ << '#' << timePs << '\n'; }
  void value(size_t index, bool known, uint64_t value) override {
    const auto& [width, code] = variables_[index];
    if (width == 1)
      out_ << (known ? (value ? '1' : '0') : 'x') << code << '\n';
    else
      out_ << 'b' << (known ? bitString(value, width) : std::string("x")) << ' ' << code << '\n';
  }
  void close() override {
    out_.close();
    if (!out_) throw std::runtime_error("error writing trace file " + path_);
  }

 private:
  std::string path_;
  std::ofstream out_;
  struct Variable {
    int width;
    std::string code;
  };
  std::vector<Variable> variables_;
};

}  // namespace

std::unique_ptr<TraceWriter> openVcdWriter(const std::string& path) {
  return std::make_unique<VcdWriter>(path);
}

}  // namespace rtu
