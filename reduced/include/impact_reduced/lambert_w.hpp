#pragma once
/// @file
/// Lambert's W function on the real axis, and the form the impact formulas need near the
/// branch point: 1 + W(-exp(-1 - s)).

namespace impact::reduced {

/// The two real branches of Lambert's W (W e^W = z).
enum class LambertBranch {
  principal, ///< W0: W >= -1, defined for z >= -1/e
  lower      ///< W-1: W <= -1, defined for -1/e <= z < 0
};

/// W0(z) for z >= -1/e: Boost.Math's value refined by one Newton step on w + log(w/z) = 0.
/// Relative error within the conditioning of W, about 2 ulps / |1 + W| (a few ulps for
/// z + 1/e >= 0.01; near -1/e the rounding of z itself dominates: use one_plus_lambert_w
/// there). Throws InvalidInput for z < -1/e or non-finite z.
double lambert_w0(double z);

/// W-1(z) for -1/e <= z < 0, refined like lambert_w0, same accuracy. Throws InvalidInput
/// outside that range.
double lambert_wm1(double z);

/// 1 + W(-exp(-1 - s)) on the chosen branch, for any s >= 0: positive on the principal
/// branch (in [0, 1)), negative on the lower one.
///
/// The argument -exp(-1 - s) approaches the branch point -1/e as s -> 0, where evaluating
/// W and adding 1 loses all digits (s = 1e-24 would leave none). Here the result y is the
/// root of the equivalent equation  -y - log(1 - y) = s,  solved by Newton's method with a
/// cancellation-free evaluation of the left side, started from the branch-point series
/// y = p - p^2/3 + p^3/36 (p = +-sqrt(2 s)) or from Boost's W away from the branch point.
/// Relative error <= 3e-16 (measured worst 2.9e-16 against 100-digit references); s = 0 gives exactly 0;
/// s up to the largest double is finite (the lower branch grows like -(s + log s)).
/// Throws InvalidInput for s < 0 or non-finite s.
double one_plus_lambert_w(double s, LambertBranch branch);

/// t - log(1 + t) for t > -1, to a few ulps relative, also for |t| << 1 where the
/// subtraction would cancel (the result is about t^2 / 2 there). Throws InvalidInput for
/// t <= -1 or non-finite t.
double log1p_excess(double t);

} // namespace impact::reduced
