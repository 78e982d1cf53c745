// Shared by the unit tests: the message of the error a call throws, to check what it says.
#pragma once
#include <exception>
#include <functional>
#include <string>

inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no error)";
}
