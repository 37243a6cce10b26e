#pragma once
// Capturing the InputError that bad input must raise, so tests can check
// what its message names.
#include <gtest/gtest.h>

#include <string>

#include "meshtrace/io/input_error.h"

namespace meshtrace::test {

// The message of the InputError that `action` throws. Records a test failure
// (and returns "") if it throws nothing or another exception type: bad input
// must never surface as bad_alloc, length_error or a crash.
template <typename Action>
std::string inputErrorOf(Action&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected an InputError, got another exception: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected an InputError, but the input was accepted";
  return "";
}

}  // namespace meshtrace::test
