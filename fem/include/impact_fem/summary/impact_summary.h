#ifndef IMPACT_FEM_SUMMARY_IMPACT_SUMMARY_H
#define IMPACT_FEM_SUMMARY_IMPACT_SUMMARY_H

#include <cstddef>
#include <vector>

namespace impact_fem
{
  /**
   * The derived quantities of an impact as pure functions of its discrete
   * history (time t_i at a constant step h, contact force F_i >= 0, approach
   * x_i, sphere velocity v_i downward positive). No deal.II, no MPI: unit
   * tested on synthetic histories (tests/fem/test_impact_summary.cpp).
   *
   * None of them depends on where a step falls beyond the accuracy of the
   * history itself:
   * - the contact phase is the first run of samples with F > 0; it ends at
   *   the first zero sample after the peak;
   * - first contact is the instant the bodies touch when the run knows it
   *   (impact-fem starts every run there: the initial gap is crossed
   *   analytically); otherwise, like the release, the zero t* of the power
   *   law F = A |t - t*|^p fitted (least squares in ln F, A, p and t* free)
   *   to the samples of that flank with F <= 25 % of the peak: a fit over
   *   tens of samples, not the last one, so the instant does not depend on
   *   which step the last contact node lets go in;
   * - the peak of the force is the vertex of the least-squares parabola
   *   through the samples within peak_window_fraction of the largest one
   *   (fitted_peak): tens of samples, so the step-to-step oscillation of a
   *   contact whose nodes enter one by one averages out instead of deciding
   *   which sample is largest, as it did through the three-point parabola
   *   (GCI of F_max 1.5 to 3 % at 5 m/s, the levels' oscillation 0.4 to
   *   0.6 %);
   * - the peak of the approach, a smooth curve, is the vertex of the
   *   parabola through the largest sample and its neighbours (error O(h^3)).
   */
  namespace summary
  {
    constexpr double nan = __builtin_nan("");

    /// First and last sample of the contact phase (both n if no contact).
    struct ContactPhase
    {
      std::size_t first = 0, last = 0;
      bool        ended = false; ///< a zero sample follows the last one
      bool
      empty(const std::size_t n) const
      {
        return first == n;
      }
    };

    ContactPhase
    contact_phase(const std::vector<double> &force);

    /**
     * Zero t* of F = A (t - t*)^p (@p rising) or A (t* - t)^p (falling)
     * fitted by least squares in ln F to the samples (t_k, F_k), k = 0..n-1
     * (increasing times, all F_k > 0, at least 3), each residual weighted by
     * @p weight[k] (all 1 if empty; else n values >= 0, at least 3
     * positive): for each t* the best (ln A, p) is linear least squares, t*
     * minimises the residual (golden section within 20 mean sample spacings
     * before the first sample, rising, or after the last, falling). Exact
     * for noise-free power-law samples of any exponent, whatever the weights.
     */
    double
    power_law_zero(const std::vector<double> &t,
                   const std::vector<double> &F,
                   const bool                 rising,
                   const std::vector<double> &weight = {});

    /// The flank of the contact phase used by power_law_zero: samples with
    /// 0 < F <= fraction * max F on the rising (falling) side of the peak.
    constexpr double flank_fraction = 0.25;

    /// Weight of a flank sample of force @p F_over_peak = F / max F in the
    /// fit: (1 - F / (flank_fraction max F))^2, zero at the flank's edge and
    /// with a zero slope there, so that the fitted zero changes continuously
    /// when a change of the step moves a sample across the edge.
    inline double
    flank_weight(const double F_over_peak)
    {
      const double u = 1 - F_over_peak / flank_fraction;
      return u > 0 ? u * u : 0.;
    }

    /// (time, value) of a peak from the parabola through the largest sample
    /// and its neighbours; the sample itself at either end of the series.
    struct Peak
    {
      double time = nan, value = nan;
    };

    Peak
    interpolated_peak(const std::vector<double> &time,
                      const std::vector<double> &values);

    /// The band below the largest sample that fitted_peak fits: 3 %. Wide
    /// enough for tens of samples at the automatic step (16 to 200 in the
    /// verified runs at 0.1 to 5 m/s), narrow enough that a smooth peak is a
    /// parabola there: for sin(pi t / T)^(3/2) the fit's vertex is off by
    /// -2e-5 of the peak (the fourth-order term), whatever the step.
    constexpr double peak_window_fraction = 0.03;

    /// The fewest samples in that band that fitted_peak fits a parabola to;
    /// with fewer it falls back to interpolated_peak.
    constexpr unsigned int peak_window_minimum_samples = 5;

    /**
     * (time, value) of the peak of a noisy series: the vertex of the
     * parabola fitted by (unweighted) least squares to the contiguous samples
     * around the largest one whose values are at least (1 -
     * peak_window_fraction) times it. Exact for a parabola; for a smooth
     * peak plus noise of amplitude epsilon, off by about epsilon / sqrt(N)
     * for N samples in the band of independent noise, and by far less for a
     * step-to-step alternation, instead of the three-point parabola's
     * epsilon. Falls back
     * to interpolated_peak where the band holds fewer than five samples,
     * touches an end of the series, or the fit is not concave with its vertex
     * inside the band (a peak not resolved by the samples).
     */
    Peak
    fitted_peak(const std::vector<double> &time,
                const std::vector<double> &values);

    /**
     * max |F_i - (F_{i-1} + F_{i+1}) / 2| / max F over the contact phase,
     * @p excluded samples at each end left out: zero for a history that is
     * linear over three steps, O(h^2 F'') for a smooth one, large for a
     * step-to-step oscillation. NaN if the phase is too short.
     */
    double
    step_oscillation(const std::vector<double> &force,
                     const unsigned int         excluded = 5);

    /// max F after the first zero sample that follows the peak, / max F
    /// (0 for a clean release; NaN if the force never returns to zero).
    double
    force_after_release(const std::vector<double> &force);

    /// Everything a run reports about its impact.
    struct ImpactSummary
    {
      double first_contact_time  = nan; ///< [s]
      double separation_time     = nan; ///< [s], NaN: no separation
      double contact_time        = nan; ///< [s]
      double force_max           = nan; ///< [N]
      double time_force_max      = nan; ///< [s]
      double approach_max        = nan; ///< [m]
      double time_approach_max   = nan; ///< [s]
      double rebound_velocity    = nan; ///< [m/s], upward at separation
      double restitution         = nan; ///< rebound / contact velocity
      double force_oscillation   = nan; ///< step_oscillation()
      double force_after_release = nan; ///< force_after_release()
    };

    /**
     * The summary of a history; @p contact_velocity is the sphere's speed
     * at first contact, @p gravity [m/s^2] acts on the free sphere after
     * separation (its effect on the final velocity is taken back to the
     * release instant); @p contact_start the instant the bodies touch if
     * known (NaN: from the rising flank).
     */
    ImpactSummary
    summarize_impact(const std::vector<double> &time,
                     const std::vector<double> &force,
                     const std::vector<double> &approach,
                     const std::vector<double> &sphere_velocity,
                     const double               contact_velocity,
                     const double               gravity,
                     const double               contact_start = nan);
  } // namespace summary
} // namespace impact_fem

#endif
