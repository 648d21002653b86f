#pragma once

#include <cctype>
#include <string>
#include <system_error>

namespace fitfeel {

// The operating system's reason a file operation failed, worded to sit inside a sentence ("cannot
// open 'a.csv': too many levels of symbolic links"): the message of the error the operation itself
// returned, so that a symlink loop reads as a loop and a refusal as "permission denied", never as
// a guess such as "does not exist".
inline std::string OsReason(const std::error_code& error) {
  std::string text = error.message();
  if (text.size() > 1 && std::isupper(static_cast<unsigned char>(text[0])) &&
      std::islower(static_cast<unsigned char>(text[1]))) {
    text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  }
  return text;
}

// The same for an errno value, read right after the failed call (a stream's open leaves the
// reason of its open(2) there). Zero, a failure the system did not report, says so.
inline std::string OsReason(int error_number) {
  if (error_number == 0) return "a failure the system gave no reason for";
  return OsReason(std::error_code(error_number, std::generic_category()));
}

}  // namespace fitfeel
