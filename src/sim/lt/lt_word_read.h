#pragma once
// The reads the loosely-timed targets serve: whole 32-bit words within one aligned line (a core
// reads Kind::kWordsPerRead words aligned to that count, docs/cycle-semantics.md "Access width and
// multi-cycle states"; an L1 reads its line from the L2, the L2 its line from the DRAM), and from
// an L1 its core's access alone. A target
// answers any other payload with an error response before it times anything: a write with
// TLM_COMMAND_ERROR_RESPONSE; an empty payload, one of part of a word or one that crosses a line
// with TLM_BURST_ERROR_RESPONSE (TLM-2.0's answer to a length the target cannot serve). The
// initiators here do not stream (streaming width = data length) and set no byte enables.

#include <cstdint>
#include <cstring>

#include <tlm>

#include "rtu/word_memory.h"

namespace rtu {

// The error response of a payload acceptWordRead refuses. Out of line: it is never taken in a run.
[[gnu::noinline]] inline void refuseWordRead(tlm::tlm_generic_payload& trans) {
  trans.set_response_status(trans.is_read() ? tlm::TLM_BURST_ERROR_RESPONSE
                                            : tlm::TLM_COMMAND_ERROR_RESPONSE);
}

// Whether `trans` is such a read within one line of `lineBytes` (a power of two); sets the error
// response when it is not. Inline, and one test in all (TLM_READ_COMMAND is 0).
inline bool acceptWordRead(tlm::tlm_generic_payload& trans, uint64_t lineBytes) {
  const uint64_t first = trans.get_address(), length = trans.get_data_length();
  const uint64_t notRead = static_cast<uint64_t>(trans.get_command()) ^ tlm::TLM_READ_COMMAND;
  // The last byte, first + length - 1, in the first byte's line: length - 1 < what is left of it
  // (an empty payload wraps to the largest length).
  const bool inLine = length - 1 < lineBytes - (first & (lineBytes - 1));
  if ((notRead | ((first | length) & 3) | !inLine) == 0) return true;
  refuseWordRead(trans);
  return false;
}

// Whether `trans` is a read of exactly `accessBytes` (a power of two, a word or more) aligned to
// them: the one access a target made for its initiator's serves (an L1, its core's; so within one
// of its lines, as the configuration checks). Sets the error response when it is not, as
// acceptWordRead. Cheaper than acceptWordRead: the L1 checks every access of a cached run.
inline bool acceptAccess(tlm::tlm_generic_payload& trans, uint64_t accessBytes) {
  const uint64_t first = trans.get_address(), length = trans.get_data_length();
  const uint64_t notRead = static_cast<uint64_t>(trans.get_command()) ^ tlm::TLM_READ_COMMAND;
  if ((notRead | (first & (accessBytes - 1)) | (length ^ accessBytes)) == 0) return true;
  refuseWordRead(trans);
  return false;
}

// Serves an accepted read (at least a word) from `words` (the image is read-only): the words from
// the payload's byte address, 0 past the image, as WordMemory reads. A single word, the SVO
// core's access, without the loop: the L1 serves one per state that reads.
inline void serveWordRead(const WordMemory& words, tlm::tlm_generic_payload& trans) {
  const uint32_t first = static_cast<uint32_t>(trans.get_address() / 4);
  const uint32_t count = trans.get_data_length() / 4;
  unsigned char* data = trans.get_data_ptr();
  const uint32_t word = words.read(first);
  std::memcpy(data, &word, sizeof word);
  for (uint32_t i = 1; i < count; ++i) {
    const uint32_t next = words.read(first + i);
    std::memcpy(data + 4 * i, &next, sizeof next);
  }
  trans.set_response_status(tlm::TLM_OK_RESPONSE);
}

}  // namespace rtu
