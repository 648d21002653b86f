#pragma once

#include <stdexcept>
#include <string>

#include "framework/core/export.h"

namespace fitfeel {

// 1-based position in a text file, as editors show it. line == 0 means "whole file".
struct SourceLocation {
  std::string file;
  int line = 0;
  int column = 0;
};

// Base of every error caused by what a user gave us (a file, a flag, a plugin folder). The CLI
// turns these into a message and exit code 2; anything else escaping is a bug (exit code 1).
class FITFEEL_API UserError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  ~UserError() override;
};

// A scenario value that is missing, malformed or out of range. what() reads
// "file:line:column: key.path: expected <expected>, found <found>".
class FITFEEL_API ScenarioError : public UserError {
 public:
  ScenarioError(SourceLocation where, std::string key_path, std::string expected,
                std::string found);
  ~ScenarioError() override;

  const SourceLocation& where() const { return where_; }
  const std::string& key_path() const { return key_path_; }
  const std::string& expected() const { return expected_; }
  const std::string& found() const { return found_; }

 private:
  SourceLocation where_;
  std::string key_path_;
  std::string expected_;
  std::string found_;
};

// A plugin that is missing, broken or incompatible; the message names what was searched and found.
class FITFEEL_API PluginError : public UserError {
 public:
  using UserError::UserError;
  ~PluginError() override;
};

// A scene the model cannot render, e.g. a surface type without a resistance law yet.
class FITFEEL_API UnsupportedError : public UserError {
 public:
  using UserError::UserError;
  ~UnsupportedError() override;
};

}  // namespace fitfeel
