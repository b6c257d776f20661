#include <impact_fem/output/checkpoint.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace impact_fem
{
  namespace checkpoint
  {
    namespace
    {
      std::string
      rank_file(const std::string &directory, const unsigned int rank)
      {
        return directory + "/rank-" + std::to_string(rank) + ".bin";
      }

      /// The directory holding the last whole checkpoint: checkpoint/, or
      /// checkpoint.old/ if the run was killed while renaming; "" if none.
      std::string
      whole_checkpoint(const std::string &run_directory)
      {
        namespace fs              = std::filesystem;
        const std::string current = directory_of(run_directory);
        if (fs::is_directory(current))
          return current;
        if (fs::is_directory(current + ".old"))
          return current + ".old";
        return "";
      }

      /// Runs @p action on the first rank of @p comm; a failure there is
      /// thrown on every rank, as "Cannot write the checkpoint @p path".
      void
      on_first_rank(const MPI_Comm               comm,
                    const std::function<void()> &action,
                    const std::string           &path)
      {
        std::string error;
        if (Utilities::MPI::this_mpi_process(comm) == 0)
          try
            {
              action();
            }
          catch (const std::exception &e)
            {
              error = e.what();
            }
        error = Utilities::MPI::broadcast(comm, error, 0);
        AssertThrow(error.empty(),
                    ExcMessage("Cannot write the checkpoint " + path + ": " +
                               error));
      }
    } // namespace


    void
    save(Writer &writer, const TrilinosWrappers::MPI::Vector &vector)
    {
      const IndexSet      owned = vector.locally_owned_elements();
      std::vector<double> values;
      values.reserve(owned.n_elements());
      std::vector<std::uint64_t> indices;
      indices.reserve(owned.n_elements());
      for (const auto i : owned)
        {
          indices.push_back(i);
          values.push_back(vector[i]);
        }
      writer &indices &values;
    }


    void
    load(Reader                        &reader,
         TrilinosWrappers::MPI::Vector &vector,
         const IndexSet                &owned,
         const MPI_Comm                 comm)
    {
      std::vector<std::uint64_t> indices;
      std::vector<double>        values;
      reader &indices           &values;
      bool                       fits =
        indices.size() == owned.n_elements() && values.size() == indices.size();
      if (fits)
        {
          std::size_t k = 0;
          for (const auto i : owned)
            fits = fits && indices[k++] == i;
        }
      AssertThrow(fits,
                  ExcMessage("The checkpoint's vector does not fit the "
                             "run's degrees of freedom."));
      vector.reinit(owned, comm);
      std::size_t k = 0;
      for (const auto i : owned)
        vector[i] = values[k++];
      vector.compress(VectorOperation::insert);
    }


    bool
    Stamp::same_run(const Stamp &other) const
    {
      return identity == other.identity &&
             step_refinement == other.step_refinement &&
             contact_spacing_halvings == other.contact_spacing_halvings &&
             entry_sub_steps == other.entry_sub_steps && ranks == other.ranks &&
             dofs == other.dofs && cells == other.cells;
    }


    std::string
    directory_of(const std::string &run_directory)
    {
      return run_directory + "/checkpoint";
    }


    void
    write(const std::string                   &run_directory,
          const Stamp                         &stamp,
          const std::function<void(Writer &)> &save,
          const MPI_Comm                       comm)
    {
      namespace fs               = std::filesystem;
      const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
      const std::string  current = directory_of(run_directory);
      const std::string  fresh   = current + ".new";
      on_first_rank(
        comm,
        [&]() {
          fs::remove_all(fresh);
          fs::create_directories(fresh);
        },
        fresh);
      bool written = false;
      try
        {
          std::ofstream out(rank_file(fresh, rank), std::ios::binary);
          {
            Writer  writer(out);
            Stamp   copy = stamp;
            writer &copy;
            save(writer);
          }
          out.close();
          written = static_cast<bool>(out);
        }
      catch (const std::exception &)
        {
          written = false;
        }
      written = !Utilities::MPI::logical_or(!written, comm);
      AssertThrow(written,
                  ExcMessage("Cannot write the checkpoint " + fresh +
                             " (a rank's file failed)."));
      // The last whole checkpoint stays readable until the new one has its
      // name.
      on_first_rank(
        comm,
        [&]() {
          fs::remove_all(current + ".old");
          if (fs::exists(current))
            fs::rename(current, current + ".old");
          fs::rename(fresh, current);
          fs::remove_all(current + ".old");
        },
        current);
    }


    bool
    read_stamp(const std::string &run_directory,
               Stamp             &stamp,
               const MPI_Comm     comm)
    {
      bool found = false;
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        try
          {
            const std::string directory = whole_checkpoint(run_directory);
            if (!directory.empty())
              {
                std::ifstream in(rank_file(directory, 0), std::ios::binary);
                if (in)
                  {
                    Reader  reader(in);
                    reader &stamp;
                    found = true;
                  }
              }
          }
        catch (const std::exception &)
          {
            found = false;
          }
      found = Utilities::MPI::broadcast(comm, found, 0);
      if (found)
        stamp = Utilities::MPI::broadcast(comm, stamp, 0);
      return found;
    }


    bool
    read(const std::string                   &run_directory,
         const Stamp                         &expected,
         Stamp                               &found,
         const std::function<void(Reader &)> &load,
         const MPI_Comm                       comm)
    {
      const std::string directory =
        Utilities::MPI::broadcast(comm, whole_checkpoint(run_directory), 0);
      if (directory.empty())
        return false;
      const unsigned int      rank = Utilities::MPI::this_mpi_process(comm);
      std::ifstream           in(rank_file(directory, rank), std::ios::binary);
      std::unique_ptr<Reader> reader;
      bool                    same = false;
      try
        {
          if (in)
            {
              reader = std::make_unique<Reader>(in);
              *reader &found;
              same = found.same_run(expected);
            }
        }
      catch (const std::exception &)
        {
          same = false;
        }
      // Every rank's part, of the same step, or none is read.
      same = !Utilities::MPI::logical_or(!same, comm);
      if (same)
        same = Utilities::MPI::min(found.step, comm) ==
               Utilities::MPI::max(found.step, comm);
      if (!same)
        return false;
      std::string error;
      try
        {
          load(*reader);
        }
      catch (const std::exception &e)
        {
          error = e.what();
        }
      const bool read_whole = !Utilities::MPI::logical_or(!error.empty(), comm);
      AssertThrow(read_whole,
                  ExcMessage("The checkpoint " + directory +
                             " of this run cannot be read" +
                             (error.empty() ? std::string(" on every rank") :
                                              ": " + error) +
                             "; remove it to start the run anew."));
      return true;
    }


    bool
    exists(const std::string &run_directory)
    {
      return !whole_checkpoint(run_directory).empty();
    }


    void
    remove(const std::string &run_directory, const MPI_Comm comm)
    {
      if (Utilities::MPI::this_mpi_process(comm) == 0)
        {
          const std::string current = directory_of(run_directory);
          std::error_code   ignored;
          std::filesystem::remove_all(current + ".new", ignored);
          std::filesystem::remove_all(current, ignored);
          std::filesystem::remove_all(current + ".old", ignored);
        }
      MPI_Barrier(comm);
    }
  } // namespace checkpoint
} // namespace impact_fem
