#include <impact_fem/summary/impact_summary.h>

#include <Eigen/QR>

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
    power_law_zero(const std::vector<double> &t,
                   const std::vector<double> &F,
                   const bool                 rising,
                   const std::vector<double> &weight)
    {
      const std::size_t n = t.size();
      auto              w = [&](const std::size_t k) {
        return weight.empty() ? 1. : weight[k];
      };
      std::vector<double> log_force(n);
      for (std::size_t k = 0; k < n; ++k)
        log_force[k] = std::log(F[k]);
      // Residual of the best (ln A, p) for a given zero.
      auto residual = [&](const double zero) {
        double              sw = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
        std::vector<double> x(n);
        for (std::size_t k = 0; k < n; ++k)
          {
            x[k] = std::log(rising ? t[k] - zero : zero - t[k]);
            sw += w(k);
            sx += w(k) * x[k];
            sy += w(k) * log_force[k];
            sxx += w(k) * x[k] * x[k];
            sxy += w(k) * x[k] * log_force[k];
          }
        const double p = (sw * sxy - sx * sy) / (sw * sxx - sx * sx);
        const double c = (sy - p * sx) / sw;
        double       r = 0;
        for (std::size_t k = 0; k < n; ++k)
          r += w(k) * (log_force[k] - c - p * x[k]) *
               (log_force[k] - c - p * x[k]);
        return r;
      };
      const double h    = (t[n - 1] - t[0]) / (n - 1);
      const double end  = rising ? t[0] : t[n - 1];
      const double sign = rising ? -1 : 1;
      // t* = end + sign s, s in (0, 20 h]: golden section on s.
      double       low = 1e-9 * h, high = 20 * h;
      const double golden = 0.5 * (std::sqrt(5.) - 1);
      double a = high - golden * (high - low), b = low + golden * (high - low);
      double ra = residual(end + sign * a), rb = residual(end + sign * b);
      for (unsigned int it = 0; it < 200 && high - low > 1e-12 * h; ++it)
        if (ra < rb)
          {
            high = b;
            b    = a;
            rb   = ra;
            a    = high - golden * (high - low);
            ra   = residual(end + sign * a);
          }
        else
          {
            low = a;
            a   = b;
            ra  = rb;
            b   = low + golden * (high - low);
            rb  = residual(end + sign * b);
          }
      return end + sign * 0.5 * (low + high);
    }


    namespace
    {
      // The index of the largest of non-empty @p values (the first of equal
      // ones).
      std::size_t
      largest_sample(const std::vector<double> &values)
      {
        return std::max_element(values.begin(), values.end()) - values.begin();
      }
    } // namespace


    Peak
    interpolated_peak(const std::vector<double> &time,
                      const std::vector<double> &values)
    {
      if (values.empty())
        return {};
      const std::size_t n = values.size(), i = largest_sample(values);
      if (i == 0 || i + 1 == n)
        return {time[i], values[i]};
      const double h    = 0.5 * (time[i + 1] - time[i - 1]);
      const double left = values[i - 1], middle = values[i],
                   right     = values[i + 1];
      const double curvature = left - 2 * middle + right; // <= 0 at a maximum
      if (!(curvature < 0))
        return {time[i], middle};
      const double offset = 0.5 * (left - right) / curvature; // in [-1/2, 1/2]
      return {time[i] + offset * h,
              middle - 0.125 * (left - right) * (left - right) / curvature};
    }


    Peak
    fitted_peak(const std::vector<double> &time,
                const std::vector<double> &values)
    {
      if (values.empty())
        return {};
      const std::size_t n = values.size(), i = largest_sample(values);
      const double      floor = (1 - peak_window_fraction) * values[i];
      std::size_t       first = i, last = i;
      while (first > 0 && values[first - 1] >= floor)
        --first;
      while (last + 1 < n && values[last + 1] >= floor)
        ++last;
      if (last - first + 1 < peak_window_minimum_samples || first == 0 ||
          last + 1 == n || !(values[i] > 0))
        return interpolated_peak(time, values);
      // Least squares for v = c0 + c1 u + c2 u^2 in u = (t - t_mid) / half
      // width, in [-1, 1] (the raw times would make the columns differ by
      // ~10^10), by Householder QR.
      const double       middle = 0.5 * (time[first] + time[last]);
      const double       half   = 0.5 * (time[last] - time[first]);
      const Eigen::Index m      = last - first + 1;
      Eigen::MatrixX3d   powers(m, 3);
      Eigen::VectorXd    band(m);
      for (Eigen::Index k = 0; k < m; ++k)
        {
          const double u = (time[first + k] - middle) / half;
          powers.row(k) << 1, u, u * u;
          band(k) = values[first + k];
        }
      const auto qr = powers.colPivHouseholderQr();
      if (qr.rank() < 3)
        return interpolated_peak(time, values);
      const Eigen::Vector3d c  = qr.solve(band);
      const double          c0 = c(0), c1 = c(1), c2 = c(2);
      if (!(c2 < 0))
        return interpolated_peak(time, values);
      const double vertex = -0.5 * c1 / c2;
      if (!(std::abs(vertex) <= 1))
        return interpolated_peak(time, values);
      return {middle + vertex * half, c0 - 0.25 * c1 * c1 / c2};
    }


    double
    step_oscillation(const std::vector<double> &force,
                     const unsigned int         excluded)
    {
      const ContactPhase phase = contact_phase(force);
      if (phase.empty(force.size()) ||
          phase.last < phase.first + 2 * excluded + 2)
        return nan;
      const double peak  = *std::max_element(force.begin(), force.end());
      double       worst = 0;
      for (std::size_t i = phase.first + excluded + 1;
           i + 1 <= phase.last - excluded;
           ++i)
        worst =
          std::max(worst,
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
                     const double               gravity,
                     const double               contact_start)
    {
      ImpactSummary      s;
      const std::size_t  n     = time.size();
      const ContactPhase phase = contact_phase(force);
      if (phase.empty(n))
        return s;

      // The flanks: samples up to flank_fraction of the peak force, weighted
      // by flank_weight so that a sample entering the flank as the step
      // changes enters with a weight that starts at zero: with equal weights
      // the fit jumped each time one did, and the release of a flank that is
      // not one power law (a plastic or a viscous unloading) moved with the
      // step like noise (observed order 0.1 over three levels).
      const std::size_t first = phase.first, last = phase.last;
      const std::size_t peak =
        std::max_element(force.begin() + first, force.begin() + last + 1) -
        force.begin();
      auto flank_zero = [&](const bool rising) {
        std::vector<double> t, F, w;
        for (std::size_t i = rising ? first : peak; i <= (rising ? peak : last);
             ++i)
          if (force[i] <= flank_fraction * force[peak])
            {
              t.push_back(time[i]);
              F.push_back(force[i]);
              w.push_back(flank_weight(force[i] / force[peak]));
            }
        if (std::count_if(w.begin(), w.end(), [](const double x) {
              return x > 0;
            }) >= 3)
          return power_law_zero(t, F, rising, w);
        // Too few samples: the step that brackets the change.
        return rising ? (first > 0 ? time[first - 1] : time[first]) :
                        (last + 1 < n ? time[last + 1] : time[last]);
      };
      s.first_contact_time =
        std::isfinite(contact_start) ? contact_start : flank_zero(true);
      if (phase.ended)
        s.separation_time = flank_zero(false);
      s.contact_time = s.separation_time - s.first_contact_time;

      const Peak force_peak    = fitted_peak(time, force);
      s.force_max              = force_peak.value;
      s.time_force_max         = force_peak.time;
      const Peak approach_peak = interpolated_peak(time, approach);
      s.approach_max           = approach_peak.value;
      s.time_approach_max      = approach_peak.time;

      if (phase.ended)
        {
          s.rebound_velocity = -(sphere_velocity[n - 1] -
                                 gravity * (time[n - 1] - s.separation_time));
          s.restitution      = s.rebound_velocity / contact_velocity;
        }
      s.force_oscillation   = step_oscillation(force);
      s.force_after_release = force_after_release(force);
      return s;
    }
  } // namespace summary
} // namespace impact_fem
