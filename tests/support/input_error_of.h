#pragma once
// The message of the InputError a piece of code throws, for tests of error messages.
#include <gtest/gtest.h>

#include <string>

#include "assets/input_error.h"

namespace pt::test {

// The InputError message of `f`, or "" (and a test failure) when it does not throw one.
template <typename F>
std::string inputErrorOf(F&& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    ADD_FAILURE() << "no InputError";
    return "";
}

}  // namespace pt::test
