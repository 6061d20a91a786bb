#include "binary_file.h"

#include <cstring>
#include <fstream>
#include <stdexcept>

namespace rtu {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__, "file formats assume a little-endian host");

std::vector<uint32_t> readWordFile(const std::string& path, size_t recordBytes,
                                   const std::string& what) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error("cannot open " + what + " '" + path + "'");
  const std::streamoff size = in.tellg();
  if (size < 0) throw std::runtime_error("cannot read " + what + " '" + path + "'");
  if (size % static_cast<std::streamoff>(recordBytes) != 0)
    throw std::runtime_error(what + " '" + path + "' has " + std::to_string(size) +
                             " bytes, not a multiple of its " + std::to_string(recordBytes) +
                             "-byte records");
  std::vector<uint32_t> words(static_cast<size_t>(size) / sizeof(uint32_t));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(words.data()), size))
    throw std::runtime_error("cannot read " + what + " '" + path + "'");
  return words;
}

void writeWordFile(const std::string& path, const std::vector<uint32_t>& words) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw std::runtime_error("cannot create '" + path + "'");
  out.write(reinterpret_cast<const char*>(words.data()),
            static_cast<std::streamsize>(words.size() * sizeof(uint32_t)));
  if (!out) throw std::runtime_error("cannot write '" + path + "'");
}

}  // namespace rtu
