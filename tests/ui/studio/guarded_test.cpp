// guarded(): a throwing call becomes one error in the message log, prefixed with what was being
// done, and the session goes on; workspace names round-trip.
#include "ui/studio/guarded.h"

#include <gtest/gtest.h>

#include <new>
#include <stdexcept>

#include "ui/studio/workspace_kind.h"

namespace polarform::studio {
namespace {

TEST(Guarded, SuccessLogsNothing) {
  MessageLog log;
  int calls = 0;
  EXPECT_TRUE(guarded(log, "Open project", [&] { ++calls; }));
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(log.size(), 0u);
}

TEST(Guarded, EachKindOfFailureBecomesOneError) {
  MessageLog log;
  EXPECT_FALSE(guarded(log, "Open project", [] { throw InputError("a.xml: line 3: bad angle"); }));
  EXPECT_FALSE(guarded(log, "Convert", [] { throw NumericalError("tolerance 1e-9 unreachable"); }));
  EXPECT_FALSE(guarded(log, "Fit", [] { throw std::bad_alloc(); }));
  EXPECT_FALSE(guarded(log, "", [] { throw std::runtime_error("disk full"); }));
  EXPECT_FALSE(guarded(log, "Solve", [] { throw 42; }));
  const auto m = log.messages();
  ASSERT_EQ(m.size(), 5u);
  EXPECT_EQ(log.error_count(), 5u);
  EXPECT_EQ(m[0].text, "Open project: a.xml: line 3: bad angle");
  EXPECT_EQ(m[1].text, "Convert: could not be computed: tolerance 1e-9 unreachable");
  EXPECT_EQ(m[2].text, "Fit: out of memory");
  EXPECT_EQ(m[3].text, "disk full");
  EXPECT_EQ(m[4].text, "Solve: unknown error");
}

TEST(Guarded, LogKeepsOrderAndSeverity) {
  MessageLog log;
  log.info("saved");
  log.warning("old format");
  log.error("broken");
  const auto m = log.messages();
  ASSERT_EQ(m.size(), 3u);
  EXPECT_EQ(m[0].severity, Severity::info);
  EXPECT_EQ(m[1].severity, Severity::warning);
  EXPECT_EQ(m[2].severity, Severity::error);
  EXPECT_LE(m[0].time, m[2].time);
  EXPECT_EQ(log.error_count(), 1u);
  log.clear();
  EXPECT_EQ(log.size(), 0u);
}

TEST(WorkspaceKind, NamesRoundTrip) {
  for (WorkspaceKind kind : kWorkspaces) EXPECT_EQ(parse_workspace(workspace_name(kind)), kind);
  EXPECT_FALSE(parse_workspace("Cam"));
  EXPECT_EQ(workspace_title(WorkspaceKind::vessel), "Vessel");
}

}  // namespace
}  // namespace polarform::studio
