#pragma once
// An output stream that writes nothing and counts the bytes it is given: the size a file would
// have, without writing it (the dry run of a trace or a timeline, src/run/trace_plan.h).

#include <cstdint>
#include <ostream>
#include <streambuf>

namespace rtu {

class CountingStream : public std::ostream {
 public:
  CountingStream() : std::ostream(&buffer_) {}
  uint64_t count() const { return buffer_.count; }

 private:
  struct Buffer : std::streambuf {
    uint64_t count = 0;
    int_type overflow(int_type c) override {
      if (!traits_type::eq_int_type(c, traits_type::eof())) ++count;
      return traits_type::not_eof(c);
    }
    std::streamsize xsputn(const char*, std::streamsize n) override {
      count += static_cast<uint64_t>(n);
      return n;
    }
  };
  Buffer buffer_;
};

}  // namespace rtu
