#include "app/input_file_check.h"

#include <stdexcept>

#include "base/input_file.h"

namespace rtu {

CLI::Validator regularInputFile() {
  return CLI::Validator(
      [](std::string& path) -> std::string {
        try {
          inputFileBytes(path, "");
        } catch (const std::runtime_error& error) {
          return error.what();
        }
        return "";
      },
      "FILE", "regular file");
}

}  // namespace rtu
