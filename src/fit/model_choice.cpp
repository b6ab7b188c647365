#include "src/fit/model_choice.h"

#include <algorithm>
#include <sstream>

#include "src/error.h"

namespace polarform {

namespace {

constexpr int kUnchosenSize = 12;  // fit_function's default net

int fixed_size(int given, int degree) {
  return given > 0 ? given : std::max(kUnchosenSize, degree + 1);
}

}  // namespace

ModelChoice choose_model(const Samples& samples, const FunctionSpace& space,
                         const FunctionFitOptions& o, const ModelChoiceOptions& m) {
  ModelChoice c{space, o, {}, {}};
  const bool free_u = o.size_u == 0 && o.max_size_u > 1, free_v = o.size_v == 0 && o.max_size_v > 1;
  const bool select = m.automatic_net && (free_u || free_v);
  NetSelection full, rot;
  if (select) full = select_net(samples, space, o);
  if (select && o.tolerance > 0.0 && full.noise_reached &&
      o.tolerance < kNoiseRefusal * full.noise) {
    std::ostringstream msg;
    msg.precision(4);
    msg << "tolerance " << o.tolerance << " mm is below the noise estimate of the data, "
        << full.noise << " mm (rms residual along the rays of the GCV-chosen " << full.size_u
        << " x " << full.size_v << " net on " << full.samples << " samples; refused below "
        << kNoiseRefusal << " of it): no fit can meet it; give a tolerance of at least "
        << kNoiseRefusal * full.noise << " mm";
    throw InputError(msg.str());
  }
  int test_u = select ? full.size_u : fixed_size(o.size_u, o.degree_u);
  const int test_v = select ? full.size_v : fixed_size(o.size_v, o.degree_v);
  if (m.revolution != RevolutionMode::no && select)
    rot = select_net(samples, rotational_space(space), rotational_options(o)), test_u = rot.size_u;
  if (m.revolution == RevolutionMode::automatic) {
    c.revolution = test_revolution(samples, space, o, test_u, test_v);
  } else {
    c.revolution.mode = m.revolution;
    c.revolution.rotational = m.revolution == RevolutionMode::yes;
    c.revolution.reason = c.revolution.rotational ? "F(u) alone was asked for (revolution yes)"
                                                  : "F(u, v) was asked for (revolution no)";
  }
  c.net = c.revolution.rotational ? rot : full;
  if (c.revolution.rotational) {
    c.space = rotational_space(space);
    c.options = rotational_options(o);
  }
  if (select && o.tolerance == 0.0) {
    c.options.size_u = c.net.size_u;
    if (!c.revolution.rotational) c.options.size_v = c.net.size_v;
  } else {
    c.net.automatic = false;
  }
  return c;
}

}  // namespace polarform
