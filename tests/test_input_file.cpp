#include <sys/stat.h>

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "base/binary_file.h"
#include "base/input_file.h"
#include "temp_path.h"

using namespace rtu;
using Catch::Contains;

TEST_CASE("an input file is a regular file whose size is known before reading", "[input_file]") {
  const TempPath file("input.bin");
  std::ofstream(file.str()) << "12345678";
  CHECK(inputFileBytes(file.str(), "SVO image") == 8);
  CHECK(readInputFile(file.str(), "SVO image", 8) == "12345678");
  CHECK_THROWS_WITH(readInputFile(file.str(), "sweep file", 7),
                    Contains("sweep file '" + file.str() + "' has 8 bytes, more than the 7"));
}

TEST_CASE("devices\\, FIFOs and directories are refused by name before they are opened",
          "[input_file]") {
  CHECK_THROWS_WITH(inputFileBytes("/dev/zero", "mesh file"),
                    "mesh file '/dev/zero' is not a regular file (a character device)");
  const TempPath fifo("input.fifo");
  REQUIRE(::mkfifo(fifo.str().c_str(), 0600) == 0);
  // Opening the FIFO would block this test forever: the check comes first.
  CHECK_THROWS_WITH(readInputFile(fifo.str(), "configuration file", 1 << 20),
                    "configuration file '" + fifo.str() + "' is not a regular file (a FIFO)");
  CHECK_THROWS_WITH(readWordFile(fifo.str(), 4, "SVO image"),
                    Contains("SVO image '" + fifo.str() + "' is not a regular file (a FIFO)"));
  const std::string directory = std::filesystem::temp_directory_path().string();
  CHECK_THROWS_WITH(readWordFile(directory, 4, "SVO image"),
                    "SVO image '" + directory + "' is not a regular file (a directory)");
  CHECK_THROWS_WITH(inputFileBytes("/nonexistent/x.svo", "SVO image"),
                    Contains("cannot open SVO image '/nonexistent/x.svo'"));
}
