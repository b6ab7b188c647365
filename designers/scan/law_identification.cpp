#include "designers/scan/law_identification.h"

#include <cmath>
#include <numbers>
#include <optional>

namespace polarform {

namespace {

constexpr MotionLaw kStandardLaws[] = {
    MotionLaw::SimpleHarmonic,       MotionLaw::Cycloidal,     MotionLaw::ModifiedTrapezoid,
    MotionLaw::ModifiedSine,         MotionLaw::Polynomial345, MotionLaw::Polynomial4567,
    MotionLaw::ConstantAcceleration, MotionLaw::Cubic,         MotionLaw::DoubleHarmonic};

// Starting fractions of the SCCA search: the family's named members and its centre.
constexpr SccaParameters kSccaStarts[] = {{0.25, 0.5, 0.25},
                                          {0.5, 0.0, 0.5},
                                          {0.0, 0.0, 1.0},
                                          {0.25, 0.0, 0.75},
                                          {1.0 / 3, 1.0 / 3, 1.0 / 3}};

}  // namespace

LawWindow motion_window(const FollowerSamples& s, const MotionPiece& piece) {
  constexpr double kTwoPi = 2 * std::numbers::pi;
  std::vector<Eigen::Index> keep;
  std::vector<double> theta;
  for (Eigen::Index k = 0; k < s.theta.size(); ++k) {
    double t = std::fmod(s.theta[k] - piece.window_start, kTwoPi);
    if (t < 0) t += kTwoPi;
    if (piece.window_start + t > piece.window_end) continue;
    keep.push_back(k);
    theta.push_back(piece.window_start + t);
  }
  LawWindow w;
  w.theta =
      Eigen::Map<const Eigen::VectorXd>(theta.data(), static_cast<Eigen::Index>(theta.size()));
  w.height.resize(w.theta.size());
  for (std::size_t i = 0; i < keep.size(); ++i)
    w.height[static_cast<Eigen::Index>(i)] = s.height[keep[i]];
  return w;
}

IdentifiedMotion identify_law(const FollowerSamples& samples, const MotionPiece& piece,
                              double noise) {
  const LawWindow w = motion_window(samples, piece);
  LawFit guess;
  guess.start = piece.start, guess.end = piece.end;
  guess.level = piece.start_level, guess.lift = piece.end_level - piece.start_level;
  IdentifiedMotion m;
  const double sigma2 = noise * noise, log_n = std::log(static_cast<double>(w.theta.size()));
  const auto bic = [&](const LawFit& f) { return f.rss / sigma2 + f.parameters * log_n; };
  const bool returning = guess.lift < 0;  // an asymmetric law returns backwards (law_fit.h)
  for (MotionLaw law : kStandardLaws)
    m.candidates.push_back(
        fit_law(w, LawShape{law, {}, returning && !is_antisymmetric_law(law)}, guess, noise));
  std::size_t best_standard = 0;
  for (std::size_t i = 1; i < m.candidates.size(); ++i)
    if (m.candidates[i].rss < m.candidates[best_standard].rss) best_standard = i;
  std::optional<LawFit> scca;
  for (const SccaParameters& start : kSccaStarts) {
    LawFit f = fit_law(w, LawShape{MotionLaw::Scca, start}, m.candidates[best_standard], noise);
    if (!scca || f.rss < scca->rss) scca = f;
  }
  m.candidates.push_back(*scca);
  for (const LawFit& f : m.candidates) m.bic.push_back(bic(f));
  for (std::size_t i = 1; i < m.bic.size(); ++i)
    if (m.bic[i] < m.bic[m.chosen]) m.chosen = i;
  // SCCA holds four standard laws: it is no rival to the one it reduces to.
  const bool member = m.law().shape.law == MotionLaw::SimpleHarmonic ||
                      m.law().shape.law == MotionLaw::Cycloidal ||
                      m.law().shape.law == MotionLaw::ModifiedTrapezoid ||
                      m.law().shape.law == MotionLaw::ModifiedSine ||
                      m.law().shape.law == MotionLaw::ConstantAcceleration;
  for (std::size_t i = 0; i < m.candidates.size(); ++i)
    if (i != m.chosen && !(member && m.candidates[i].shape.law == MotionLaw::Scca) &&
        m.candidates[i].rss - m.law().rss < kIndistinguishableChi2 * sigma2)
      m.indistinguishable.push_back(i);
  m.kind = m.law().lift > 0 ? SegmentKind::Rise : SegmentKind::Return;
  return m;
}

}  // namespace polarform
