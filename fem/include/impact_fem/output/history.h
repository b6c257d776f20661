#ifndef IMPACT_FEM_OUTPUT_HISTORY_H
#define IMPACT_FEM_OUTPUT_HISTORY_H

#include <impact_fem/output/checkpoint.h>

#include <map>
#include <string>
#include <vector>

namespace impact_fem
{
  /**
   * Per-step histories of a run, kept in memory on rank 0 and written as one
   * HDF5 file: one 1D dataset per quantity with the attributes "unit" and
   * "description"; run attributes (parameters, derived results) on the root.
   *
   * The file is written under a temporary name and renamed when complete, so
   * no reader ever sees a truncated file; an unfinished run is written as
   * <name>.incomplete.h5 with the root attribute status = "incomplete".
   */
  class History
  {
  public:
    /// Declare a quantity; the order of declaration is the order in the file.
    void
    declare(const std::string &name,
            const std::string &unit,
            const std::string &description);

    /// A quantity as declared: name, unit, description.
    struct Column
    {
      std::string name, unit, description;
    };

    /// Declare several quantities, in order.
    void
    declare(const std::vector<Column> &columns)
    {
      for (const auto &c : columns)
        declare(c.name, c.unit, c.description);
    }

    /// Append the value of a declared quantity for the current step.
    void
    append(const std::string &name, const double value);

    const std::vector<double> &
    operator[](const std::string &name) const;

    /// Whether the quantity @p name is declared.
    bool
    has(const std::string &name) const
    {
      return index.count(name) > 0;
    }

    /// A dataset that is not per step (e.g. a pressure profile); replaced
    /// on each call.
    void
    set_profile(const std::string         &name,
                const std::string         &unit,
                const std::string         &description,
                const std::vector<double> &values);

    /// The profile @p name as last set; empty when it was never set.
    const std::vector<double> &
    profile(const std::string &name) const;

    std::size_t
    n_steps() const;

    /// The values of every quantity and the profiles, for a checkpoint.
    void
    save(checkpoint::Writer &writer) const;

    /// Reads what save() wrote; the quantities must be declared as they
    /// were (the same postprocessors), or it throws.
    void
    load(checkpoint::Reader &reader);

    void
    write_hdf5(const std::string                        &filename,
               const std::map<std::string, std::string> &text_attributes,
               const std::map<std::string, double>      &numeric_attributes,
               const bool                                complete) const;

  private:
    struct Series
    {
      std::string         name, unit, description;
      std::vector<double> values;
    };
    std::vector<Series>                series;
    std::vector<Series>                profiles;
    std::map<std::string, std::size_t> index;
  };
} // namespace impact_fem

#endif
