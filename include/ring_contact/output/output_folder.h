// Files that survive: the results of a run are never lost (a file on disk is
// always whole: written under a temporary name and renamed, or grown by
// whole rows that reach the disk before the next step) and never mixed (one
// run holds its output folder and first removes what an earlier run left).
#ifndef ring_contact_output_output_folder_h
#define ring_contact_output_output_folder_h

#include <string>
#include <vector>

namespace RingContact
{
  /// The temporary name a file is written under before it is renamed:
  /// ".<name>.tmp" in the same folder (hidden, so that ParaView's file
  /// groups do not list it).
  std::string
  temporary_name(const std::string &filename);

  /// Replace `filename` by `contents` atomically (temporary, fsync, rename).
  void
  write_file_atomically(const std::string &filename,
                        const std::string &contents);

  /// A text file that grows by whole lines: each append() is on disk
  /// (written and fsync'ed) when it returns. If a write fails (disk full,
  /// file size limit), the file is cut back to its last whole line and the
  /// error is thrown, naming the file.
  class AppendOnlyFile
  {
  public:
    /// Create (or empty) the file and write `header`.
    AppendOnlyFile(const std::string &filename, const std::string &header);
    ~AppendOnlyFile();
    AppendOnlyFile(const AppendOnlyFile &) = delete;
    AppendOnlyFile &
    operator=(const AppendOnlyFile &) = delete;

    void
    append(const std::string &text);

  private:
    const std::string filename;
    int               descriptor;
    long long         size; ///< bytes of whole lines on disk
  };

  /// The output folder of a run, held for the run's lifetime: a lock
  /// (flock on ".ring_contact.lock", which records the pid) keeps a second
  /// run out while this one lives; the lock goes with the process, however
  /// it ends.
  class OutputFolder
  {
  public:
    /// Create the folder if needed and take it; throws, naming the folder
    /// and the pid of the run that holds it, if another run does. Throws
    /// too if a folder that no run of this program has used (no lock file)
    /// holds files with its results' names: they are somebody else's, and
    /// this program would replace them.
    explicit OutputFolder(const std::string &directory);
    ~OutputFolder();
    OutputFolder(const OutputFolder &) = delete;
    OutputFolder &
    operator=(const OutputFolder &) = delete;

    /// Remove the files an earlier run of this program left in the folder
    /// (history.csv, verdicts.csv, solution-*.vtu/.pvd, slave-*.vtu/.pvd and
    /// their temporaries; nothing else) and return their names, sorted.
    /// Called once the run has shown it can start (its input read, its
    /// mesh made and checked): a run that fails before leaves them.
    std::vector<std::string>
    remove_earlier_results() const;

    /// Whether `name` (without folder) is a file this program writes.
    static bool
    is_result_file(const std::string &name);

  private:
    const std::string directory;
    int               lock_descriptor;
  };
} // namespace RingContact

#endif
