#ifndef IMPACT_FEM_OUTPUT_CHECKPOINT_H
#define IMPACT_FEM_OUTPUT_CHECKPOINT_H

#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_vector.h>

#include <boost/archive/binary_iarchive.hpp>
#include <boost/archive/binary_oarchive.hpp>
#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cstdint>
#include <functional>
#include <string>

namespace impact_fem
{
  /**
   * The state of an impact at the end of a step, kept beside its history so
   * that a run stopped before its end (killed, interrupted, out of the
   * machine's time) goes on from there when it is made again with the same
   * entries on the same number of ranks, instead of from the first contact.
   *
   * A checkpoint is the directory `checkpoint/` of the run: one binary file
   * per rank (rank-<r>.bin, Boost.Serialization's binary archive of the
   * rank's part of the state: the locally owned entries of the vectors, the
   * quadrature-point states of its owned cells), each beginning with the
   * Stamp of the run it belongs to. The doubles are written as they are in
   * memory, so that a resumed run continues bit for bit as the run it
   * resumes. Each component that carries state from one step to the next
   * writes and reads its own part (save() and load() of the time stepper,
   * the internal variables, the contact, the history, each postprocessor).
   *
   * Written whole or not at all: into checkpoint.new/, then renamed over the
   * last one (kept as checkpoint.old/ until the rename is done, and read if
   * the run was killed in between). Removed when the run is complete, or
   * when it is made again with a finer step or denser contact nodes. The
   * archives are those of the machine and Boost version that wrote them: a
   * checkpoint is for the same build to go on, not an exchange format.
   */
  namespace checkpoint
  {
    using namespace dealii;
    using Writer = boost::archive::binary_oarchive;
    using Reader = boost::archive::binary_iarchive;

    /// The locally owned entries of @p vector, with their index set.
    void
    save(Writer &writer, const TrilinosWrappers::MPI::Vector &vector);

    /// Reads what save() wrote into @p vector, made with the locally owned
    /// entries @p owned on @p comm; throws if the entries differ from the
    /// saved ones (another mesh or partition).
    void
    load(Reader                        &reader,
         TrilinosWrappers::MPI::Vector &vector,
         const IndexSet                &owned,
         const MPI_Comm                 comm);

    /**
     * What a checkpoint belongs to: a run resumes only from the checkpoint
     * of the same run. @p identity is the run identity of its entries
     * (run_identity::of(): the entries that cannot change the result left
     * out), the refinement is the one the energy balance asked for (a run
     * made again with a finer step is another run), and the ranks, degrees
     * of freedom and cells must match for the parts of the files to fit.
     */
    struct Stamp
    {
      static constexpr unsigned int format = 1;

      std::string   identity;
      double        step_refinement          = 1;
      unsigned int  contact_spacing_halvings = 0;
      unsigned int  entry_sub_steps          = 1;
      unsigned int  ranks                    = 0;
      std::uint64_t dofs                     = 0;
      std::uint64_t cells                    = 0;

      /// The step and time reached [-, s] (not part of the match).
      unsigned int step = 0;
      double       time = 0;

      /// Same run: every field but the step and time equal.
      bool
      same_run(const Stamp &other) const;

      template <class Archive>
      void
      serialize(Archive &archive, const unsigned int)
      {
        unsigned int version = format;
        archive     &version;
        if (version != format)
          throw std::runtime_error("checkpoint format " +
                                   std::to_string(version) + ", expected " +
                                   std::to_string(format));
        archive &identity &step_refinement &contact_spacing_halvings
          &entry_sub_steps &ranks &dofs &cells &step &time;
      }
    };

    /// The checkpoint directory of the run in @p run_directory.
    std::string
    directory_of(const std::string &run_directory);

    /**
     * Writes the checkpoint of @p stamp, each rank its part by @p save
     * (collective over @p comm): checkpoint.new/, then renamed to
     * checkpoint/. Throws on an I/O error (on every rank).
     */
    void
    write(const std::string                   &run_directory,
          const Stamp                         &stamp,
          const std::function<void(Writer &)> &save,
          const MPI_Comm                       comm);

    /**
     * The stamp of the run's checkpoint as the first rank reads it
     * (broadcast to all of @p comm), or false if there is none that can be
     * read. Only the stamp is read.
     */
    bool
    read_stamp(const std::string &run_directory,
               Stamp             &stamp,
               const MPI_Comm     comm);

    /**
     * Reads the checkpoint into the run (collective over @p comm) if its
     * stamp is the same run as @p expected on every rank; @p load reads
     * each rank's part. Returns the stamp read (its step and time), or
     * false, having read nothing, when there is no checkpoint of this run.
     * Throws if a checkpoint of this run cannot be read whole.
     */
    bool
    read(const std::string                   &run_directory,
         const Stamp                         &expected,
         Stamp                               &found,
         const std::function<void(Reader &)> &load,
         const MPI_Comm                       comm);

    /// Whether the run in @p run_directory has a checkpoint (of any run;
    /// not collective).
    bool
    exists(const std::string &run_directory);

    /// Removes the run's checkpoint, if any (first rank; collective).
    void
    remove(const std::string &run_directory, const MPI_Comm comm);
  } // namespace checkpoint
} // namespace impact_fem

#endif
