#pragma once
// A call the tests expect refused: it throws std::runtime_error whose message names what it must
// (the file, the dataset, the version).
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace grainlab::test {

/// Runs `call`, which must throw std::runtime_error naming each of `words`; when it returns, a
/// fatal failure says `ifNot`. Call it within ASSERT_NO_FATAL_FAILURE.
template <class Call>
void expectRefusedNaming(Call call, const std::vector<std::string>& words,
                         const std::string& ifNot) {
    try {
        call();
        FAIL() << ifNot;
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        for (const std::string& word : words) {
            EXPECT_NE(what.find(word), std::string::npos) << what;
        }
    }
}

} // namespace grainlab::test
