#include <impact_fem/summary/impact_summary.h>

#include <algorithm>
#include <cmath>

namespace impact_fem
{
  namespace summary
  {
    ContactPhase
    contact_phase(const std::vector<double> &force)
    {
      const std::size_t n = force.size();
      ContactPhase      phase{n, n, false};
      for (std::size_t i = 0; i < n; ++i)
        if (force[i] > 0)
          {
            if (phase.first == n)
              phase.first = i;
            phase.last = i;
          }
        else if (phase.first != n)
          {
            phase.ended = true;
            break;
          }
      return phase;
    }


    double
    power_law_zero(const double t[3], const double F[3], const bool rising)
    {
      // Distances s_k = |t_k - t*| grow (rising) or shrink (falling) by h
      // per sample. With sigma = s_near / h (s_near: the distance of the
      // sample next to the zero) the ratio
      //   R = ln(F_far / F_mid) / ln(F_mid / F_near)
      //     = ln((sigma + 2) / (sigma + 1)) / ln((sigma + 1) / sigma)
      // does not depend on A or p and rises from 0 (sigma -> 0) to 1
      // (sigma -> infinity): one bisection in sigma in (0, 1].
      const double h      = (t[2] - t[0]) / 2;
      const double F_near = rising ? F[0] : F[2];
      const double F_far  = rising ? F[2] : F[0];
      const double t_near = rising ? t[0] : t[2];
      const double sign   = rising ? -1 : 1; // t* = t_near + sign sigma h
      const double F_mid  = F[1];
      if (!(F_near > 0 && F_mid > F_near && F_far > F_mid))
        return t_near + sign * h; // not a growing power law: bracket end
      const double measured = std::log(F_far / F_mid) / std::log(F_mid / F_near);
      auto ratio = [](const double sigma) {
        return std::log((sigma + 2) / (sigma + 1)) / std::log((sigma + 1) / sigma);
      };
      if (measured >= ratio(1.))
        return t_near + sign * h;
      double low = 0, high = 1;
      for (unsigned int it = 0; it < 200 && high - low > 1e-15; ++it)
        {
          const double middle = 0.5 * (low + high);
          (ratio(middle) < measured ? low : high) = middle;
        }
      return t_near + sign * 0.5 * (low + high) * h;
    }


    Peak
    interpolated_peak(const std::vector<double> &time,
                      const std::vector<double> &values)
    {
      const std::size_t n = values.size();
      if (n == 0)
        return {};
      const std::size_t i =
        std::max_element(values.begin(), values.end()) - values.begin();
      if (i == 0 || i + 1 == n)
        return {time[i], values[i]};
      const double h     = 0.5 * (time[i + 1] - time[i - 1]);
      const double left  = values[i - 1], middle = values[i],
                   right = values[i + 1];
      const double curvature = left - 2 * middle + right; // <= 0 at a maximum
      if (!(curvature < 0))
        return {time[i], middle};
      const double offset = 0.5 * (left - right) / curvature; // in [-1/2, 1/2]
      return {time[i] + offset * h,
              middle - 0.125 * (left - right) * (left - right) / curvature};
    }


    double
    step_oscillation(const std::vector<double> &force,
                     const unsigned int          excluded)
    {
      const ContactPhase phase = contact_phase(force);
      if (phase.empty(force.size()) ||
          phase.last < phase.first + 2 * excluded + 2)
        return nan;
      const double peak = *std::max_element(force.begin(), force.end());
      double       worst = 0;
      for (std::size_t i = phase.first + excluded + 1;
           i + 1 <= phase.last - excluded;
           ++i)
        worst = std::max(worst,
                         std::abs(force[i] - 0.5 * (force[i - 1] + force[i + 1])));
      return worst / peak;
    }


    double
    force_after_release(const std::vector<double> &force)
    {
      if (force.empty())
        return nan;
      const std::size_t peak =
        std::max_element(force.begin(), force.end()) - force.begin();
      std::size_t zero = peak;
      while (zero < force.size() && force[zero] > 0)
        ++zero;
      if (zero == force.size() || !(force[peak] > 0))
        return nan;
      return *std::max_element(force.begin() + zero, force.end()) / force[peak];
    }


    ImpactSummary
    summarize_impact(const std::vector<double> &time,
                     const std::vector<double> &force,
                     const std::vector<double> &approach,
                     const std::vector<double> &sphere_velocity,
                     const double               contact_velocity,
                     const double               gravity)
    {
      ImpactSummary      s;
      const std::size_t  n     = time.size();
      const ContactPhase phase = contact_phase(force);
      if (phase.empty(n))
        return s;

      // Three positive samples at each end when there are; a shorter
      // contact is bracketed by its steps.
      const std::size_t first = phase.first, last = phase.last;
      if (last >= first + 2)
        s.first_contact_time = power_law_zero(&time[first], &force[first], true);
      else
        s.first_contact_time = first > 0 ? time[first - 1] : time[first];
      if (phase.ended)
        s.separation_time = last >= first + 2 ?
                              power_law_zero(&time[last - 2], &force[last - 2], false) :
                              time[last + 1];
      s.contact_time = s.separation_time - s.first_contact_time;

      const Peak force_peak = interpolated_peak(time, force);
      s.force_max           = force_peak.value;
      s.time_force_max      = force_peak.time;
      const Peak approach_peak = interpolated_peak(time, approach);
      s.approach_max           = approach_peak.value;
      s.time_approach_max      = approach_peak.time;

      if (phase.ended)
        {
          s.rebound_velocity =
            -(sphere_velocity[n - 1] - gravity * (time[n - 1] - s.separation_time));
          s.restitution = s.rebound_velocity / contact_velocity;
        }
      s.force_oscillation   = step_oscillation(force);
      s.force_after_release = force_after_release(force);
      return s;
    }
  } // namespace summary
} // namespace impact_fem
