// Bounded mutation fuzzing, shared by the fuzz tests of every parser polarform owns (point clouds
// in tests of src/io, project files in tests of jobs/project, the studio's --script in tests of
// ui/studio). Each valid seed is mutated (byte flips, deletions, duplications, insertions of
// number-breaking tokens, truncation) with a fixed seed; every mutant must either parse into a
// valid result or throw InputError — no other exception, no crash (run `make asan` for memory
// errors). POLARFORM_FUZZ_ITERATIONS scales the run (default 10000 mutants per seed).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <iterator>
#include <random>
#include <string>
#include <typeinfo>

#include "src/error.h"

namespace polarform::fuzz_test {

inline int iterations() {
  const char* env = std::getenv("POLARFORM_FUZZ_ITERATIONS");
  return env ? std::max(1, std::atoi(env)) : 10000;
}

// One mutation of `s`, drawn from `rng`.
inline std::string mutate(std::string s, std::mt19937_64& rng) {
  static const char* const kTokens[] = {"nan", "inf", "-", "1e999", "0x", ",", "\n", " ", "\0",
                                        "element vertex 99999999999\n", "<", "\"", "=", "/>",
                                        "property list uchar int x\n", "end_header\n", "-1"};
  const auto pick = [&](std::size_t n) {
    return n == 0 ? std::size_t{0} : static_cast<std::size_t>(rng() % n);
  };
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits; ++e) {
    const std::size_t at = pick(s.size() + 1);
    switch (rng() % 6) {
      case 0:
        if (!s.empty()) s[pick(s.size())] ^= static_cast<char>(1u << (rng() % 8));
        break;
      case 1:
        s.erase(std::min(at, s.size()), pick(16) + 1);
        break;
      case 2: {
        const std::size_t from = pick(s.size());
        s.insert(at, s.substr(from, pick(24) + 1));
        break;
      }
      case 3: {
        const char* token = kTokens[pick(std::size(kTokens))];
        s.insert(at, token, std::max<std::size_t>(1, std::strlen(token)));
        break;
      }
      case 4:
        s.resize(std::min(at, s.size()));
        break;
      default:
        if (!s.empty()) s[pick(s.size())] = static_cast<char>(rng() % 256);
        break;
    }
  }
  return s;
}

// Feeds `count` mutants of `seed` to `parse`; counts accepted and rejected ones.
inline void fuzz(const std::string& seed, const std::function<void(const std::string&)>& parse,
                 std::uint64_t rng_seed, int count) {
  ASSERT_NO_THROW(parse(seed)) << "the seed itself must parse";
  std::mt19937_64 rng(rng_seed);
  int rejected = 0;
  for (int k = 0; k < count; ++k) {
    const std::string input = mutate(seed, rng);
    try {
      parse(input);
    } catch (const InputError&) {
      ++rejected;
    } catch (const std::exception& e) {
      FAIL() << "mutant " << k << " threw " << typeid(e).name() << ": " << e.what();
    }
  }
  // A fuzzer whose mutants all pass tests nothing; one whose mutants all fail may never reach
  // past the first check — both would make this test meaningless.
  EXPECT_GT(rejected, count / 20);
}

}  // namespace polarform::fuzz_test
