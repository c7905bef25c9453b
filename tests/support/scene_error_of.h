#pragma once
// The message of the SceneError a call throws, for tests of located error messages.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "candela/core/error.h"

namespace candela::test {

// The message of the SceneError that `f` throws; fails the test when it throws nothing.
inline std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const SceneError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a SceneError";
    return "";
}

}  // namespace candela::test
