// @sect3{Files that survive: the results folder}
//
// A run's results must never be lost or mixed. Killed runs used to leave no
// history.csv, empty .pvd or truncated .vtu files; a full disk lost every
// converged step; two runs into one folder mixed their files. So every file
// the program writes is whole on disk at any moment: a file that is
// replaced (a VTU, a PVD, verdicts.csv) is written under a temporary name,
// flushed to disk and renamed over the old one, which POSIX makes atomic;
// a file that grows (history.csv) grows by whole lines, each on disk
// before the next step. And one run at a time holds its folder, by a lock
// that the kernel releases however the process ends.
//
// These are plain POSIX calls (open, fsync, rename, flock): the C++
// streams neither fsync nor say which system call failed and why.
#include <ring_contact/output/output_folder.h>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <regex>
#include <stdexcept>

namespace RingContact
{
  namespace
  {
    // Every failure is one line that names the file and the system's
    // reason (a full disk, a file size limit, no permission).
    [[noreturn]] void
    fail(const std::string &what, const std::string &filename, const int error)
    {
      throw std::runtime_error("cannot " + what + " '" + filename +
                               "': " + std::strerror(error));
    }

    // write() until everything is written; false (errno set) on failure.
    // One write() may write less than asked (near a full disk or a file
    // size limit) or be interrupted by a signal before writing anything:
    // both are retried, the first with the rest of the data.
    bool
    write_all(const int descriptor, const char *data, std::size_t n)
    {
      while (n > 0)
        {
          const ssize_t written = ::write(descriptor, data, n);
          if (written < 0)
            {
              if (errno == EINTR)
                continue;
              return false;
            }
          data += written;
          n -= static_cast<std::size_t>(written);
        }
      return true;
    }

    // A file name without folder is in the current folder: fsync needs
    // a name to open.
    std::string
    folder_of(const std::string &filename)
    {
      const std::string folder =
        std::filesystem::path(filename).parent_path().string();
      return folder.empty() ? "." : folder;
    }

    // Make the creation or removal of files in `folder` durable. Some file
    // systems cannot fsync a folder (EINVAL): it is then as durable as they
    // make it. Not done after each rename: the data of a renamed file is on
    // disk (fsync) before the rename, which a killed process cannot undo;
    // that the rename itself survives a power loss is left to the file
    // system (ext4 commits it within seconds), as a folder fsync per file made
    // each step's output much slower (doc/validation.md, "Time and memory
    // behind the code's choices").
    void
    sync_folder(const std::string &folder)
    {
      const int descriptor = ::open(folder.c_str(), O_RDONLY | O_CLOEXEC);
      if (descriptor < 0)
        return;
      ::fsync(descriptor);
      ::close(descriptor);
    }

    // The temporary is made new (O_CREAT | O_EXCL), never opened: a
    // symbolic link planted under its name would otherwise have its target
    // written (or created, if it pointed nowhere yet), and a hard link would
    // share the truncated contents with another name. A regular file there is
    // a temporary that a killed run left: its name is removed (what another
    // name of it holds is untouched) and the file made anew. A symbolic link
    // is refused with its name, like the lock file's (OutputFolder): this
    // program does not follow links in its folder, and does not remove one
    // it did not make either.
    int
    open_temporary(const std::string &temporary, const std::string &filename)
    {
      for (int attempt = 0; attempt < 3; ++attempt)
        {
          const int descriptor =
            ::open(temporary.c_str(),
                   O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW,
                   0644);
          if (descriptor >= 0)
            return descriptor;
          if (errno != EEXIST)
            fail("write", filename, errno);
          struct stat status;
          if (::lstat(temporary.c_str(), &status) != 0)
            continue; // gone since: try again
          if (!S_ISREG(status.st_mode))
            throw std::runtime_error(
              "cannot write '" + filename + "': its temporary file '" +
              temporary + "' is " +
              (S_ISLNK(status.st_mode) ?
                 "a symbolic link, which this program does not follow "
                 "(what it points to is left as it is)" :
                 "not a regular file") +
              ": remove it, or choose another Output/Directory");
          if (::unlink(temporary.c_str()) != 0 && errno != ENOENT)
            fail("remove the leftover temporary file", temporary, errno);
        }
      throw std::runtime_error("cannot write '" + filename +
                               "': its temporary file '" + temporary +
                               "' reappears as soon as it is removed");
    }
  } // namespace

  // @sect4{Whole files: temporary, fsync, rename}
  //
  // The temporary is in the same folder as the file, so that the rename
  // stays within one file system (across two it fails); the leading dot
  // hides it from ParaView's file groups, and remove_earlier_results()
  // knows it by its name.
  std::string
  temporary_name(const std::string &filename)
  {
    const std::filesystem::path path(filename);
    return (path.parent_path() / ("." + path.filename().string() + ".tmp"))
      .string();
  }

  void
  write_file_atomically(const std::string &filename,
                        const std::string &contents)
  {
    const std::string temporary  = temporary_name(filename);
    const int         descriptor = open_temporary(temporary, filename);
    if (!write_all(descriptor, contents.data(), contents.size()) ||
        ::fsync(descriptor) != 0)
      {
        const int error = errno;
        ::close(descriptor);
        ::unlink(temporary.c_str());
        fail("write", filename, error);
      }
    // close() can report a write error of its own (on a network file
    // system, data may be sent only then).
    if (::close(descriptor) != 0)
      {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail("write", filename, error);
      }
    if (::rename(temporary.c_str(), filename.c_str()) != 0)
      {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail("rename a temporary file to", filename, error);
      }
  }

  // @sect4{A file that grows by whole lines}
  //
  // history.csv: truncated when the run starts it (it belongs to this run
  // alone), then appended to at every converged step. The folder is
  // fsync'ed once, so that the file's creation itself survives a crash.
  AppendOnlyFile::AppendOnlyFile(const std::string &filename,
                                 const std::string &header)
      : filename(filename)
      , descriptor(::open(filename.c_str(),
                          O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW,
                          0644))
      , size(0)
  {
    if (descriptor < 0)
      fail("write", filename, errno);
    sync_folder(folder_of(filename));
    try
      {
        append(header);
      }
    catch (...)
      {
        ::close(descriptor);
        throw;
      }
  }

  AppendOnlyFile::~AppendOnlyFile()
  {
    ::close(descriptor);
  }

  void
  AppendOnlyFile::append(const std::string &text)
  {
    if (!write_all(descriptor, text.data(), text.size()) ||
        ::fsync(descriptor) != 0)
      {
        const int error = errno;
        // Cut a partly written line off: the file keeps its whole lines.
        // `size` counts the bytes of the lines known to be on disk; the
        // descriptor's offset is moved back to it too, so that a later
        // append does not leave a hole where the cut line was.
        if (::ftruncate(descriptor, size) == 0)
          {
            ::lseek(descriptor, size, SEEK_SET);
            ::fsync(descriptor);
          }
        fail("write", filename, error);
      }
    size += static_cast<long long>(text.size());
  }

  // @sect4{The folder held by one run}
  //
  // flock() on a lock file in the folder: exclusive, and without waiting
  // (LOCK_NB), so that a second run into the folder is refused at once
  // with the holder's pid, rather than left to wait. The kernel releases
  // the lock when the descriptor is closed, also when the process is
  // killed: no stale lock survives its run.
  OutputFolder::OutputFolder(const std::string &directory)
      : directory(directory)
      , lock_descriptor(-1)
  {
    // With its parents: the default results/<prm name> under a results/
    // that may not exist yet.
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
      throw std::runtime_error("cannot create the output folder '" + directory +
                               "': " + error.message());
    // The lock file is also the mark of a folder this program has written
    // in: only there are files with its results' names its own.
    // O_NOFOLLOW: a symbolic link planted under the lock's name would
    // otherwise get its target overwritten with our pid.
    // symlink_status: a link planted under the lock's name counts as
    // there (and is refused below), not as the absence of its target.
    const std::string lock_name = directory + "/.ring_contact.lock";
    const bool        used_before =
      std::filesystem::exists(std::filesystem::symlink_status(lock_name));
    lock_descriptor = ::open(lock_name.c_str(),
                             O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW,
                             0644);
    if (lock_descriptor < 0 && errno == ELOOP)
      throw std::runtime_error(
        "the output folder's lock file '" + lock_name +
        "' is a symbolic link, which this program does not follow: remove "
        "it, or choose another Output/Directory");
    if (lock_descriptor < 0)
      fail("create the lock file", lock_name, errno);
    // The holder's pid, written by it below, makes the refusal
    // actionable; a lock file read while its holder writes it may be
    // empty, hence "unknown".
    if (::flock(lock_descriptor, LOCK_EX | LOCK_NB) != 0)
      {
        const int     error   = errno;
        char          pid[32] = {};
        const ssize_t n = ::pread(lock_descriptor, pid, sizeof(pid) - 1, 0);
        ::close(lock_descriptor);
        if (error != EWOULDBLOCK)
          fail("lock", lock_name, error);
        std::string holder(pid, n > 0 ? static_cast<std::size_t>(n) : 0);
        holder.erase(std::remove(holder.begin(), holder.end(), '\n'),
                     holder.end());
        throw std::runtime_error(
          "the output folder '" + directory +
          "' is in use by another run of ring_contact (pid " +
          (holder.empty() ? std::string("unknown") : holder) +
          "); wait for it to end or choose another Output/Directory");
      }
    // A folder without the lock file was never written by this program:
    // files there with its results' names are somebody else's, and this
    // run would replace them. The refusal removes the lock file just made,
    // so that the folder stays as it was and is refused again next time.
    if (!used_before)
      {
        std::vector<std::string> foreign;
        for (const auto &entry : std::filesystem::directory_iterator(directory))
          if (entry.is_regular_file() &&
              is_result_file(entry.path().filename().string()))
            foreign.push_back(entry.path().filename().string());
        if (!foreign.empty())
          {
            std::sort(foreign.begin(), foreign.end());
            ::close(lock_descriptor);
            ::unlink(lock_name.c_str());
            throw std::runtime_error(
              "the output folder '" + directory + "' holds '" + foreign[0] +
              "'" +
              (foreign.size() > 1 ?
                 " and " + std::to_string(foreign.size() - 1) + " more file" +
                   (foreign.size() > 2 ? "s" : "") :
                 std::string()) +
              " named as this program's results, which no run of it wrote "
              "there (the folder has no .ring_contact.lock) and this run "
              "would replace: move them, or choose another Output/Directory");
          }
      }
    // The lock is ours: record our pid for the message above. Truncated
    // first, so that a shorter pid leaves nothing of a longer one.
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(lock_descriptor, 0) != 0 ||
        ::pwrite(lock_descriptor, pid.data(), pid.size(), 0) !=
          static_cast<ssize_t>(pid.size()))
      {
        const int error = errno;
        ::close(lock_descriptor);
        fail("write", lock_name, error);
      }
  }

  OutputFolder::~OutputFolder()
  {
    // The lock file stays (removing it would race with a run waiting for
    // it); closing releases the lock.
    ::close(lock_descriptor);
  }

  bool
  OutputFolder::is_result_file(const std::string &name)
  {
    // The names VtuWriter, the history, the verdicts, the record of the
    // parameters and the run's log use (scheme tags
    // are lower-case letters, digits and hyphens; an MPI run writes each
    // process's piece as solution-<tag>-<step>.<process>.vtu and the
    // .pvtu that lists them), and their temporaries.
    static const std::regex result(
      "(history\\.csv|verdicts\\.csv|used_parameters\\.prm|run\\.log|"
      "(solution|slave)-[a-z0-9-]+-[0-9]+(\\.[0-9]+)?\\.vtu|"
      "solution-[a-z0-9-]+-[0-9]+\\.pvtu|"
      "(solution|slave)-[a-z0-9-]+\\.pvd)");
    static const std::regex temporary("\\.(.+)\\.tmp");
    std::smatch             match;
    if (std::regex_match(name, match, temporary))
      return std::regex_match(match[1].str(), result);
    return std::regex_match(name, result);
  }

  // Only regular files with the program's result names go: the folder may
  // hold the user's own files. Called just before the first step (the
  // start observer in run.cc), not when the folder is taken: a run that
  // failed on its mesh or boundaries used to wipe the previous results and
  // leave none.
  std::vector<std::string>
  OutputFolder::remove_earlier_results() const
  {
    std::vector<std::string> removed;
    for (const auto &entry : std::filesystem::directory_iterator(directory))
      {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && is_result_file(name))
          {
            std::error_code error;
            std::filesystem::remove(entry.path(), error);
            if (error)
              throw std::runtime_error(
                "cannot remove '" + entry.path().string() +
                "' (left by an earlier run): " + error.message());
            removed.push_back(name);
          }
      }
    std::sort(removed.begin(), removed.end());
    if (!removed.empty())
      sync_folder(directory);
    return removed;
  }
} // namespace RingContact
