#include <ring_contact/output_folder.h>

#include <fcntl.h>
#include <sys/file.h>
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
    [[noreturn]] void
    fail(const std::string &what, const std::string &filename, const int error)
    {
      throw std::runtime_error("cannot " + what + " '" + filename +
                               "': " + std::strerror(error));
    }

    // write() until everything is written; false (errno set) on failure.
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
    // system (ext4 commits it within seconds), as a folder fsync per file
    // about doubled the cost of each step's output.
    void
    sync_folder(const std::string &folder)
    {
      const int descriptor = ::open(folder.c_str(), O_RDONLY | O_CLOEXEC);
      if (descriptor < 0)
        return;
      ::fsync(descriptor);
      ::close(descriptor);
    }
  } // namespace

  std::string
  temporary_name(const std::string &filename)
  {
    const std::filesystem::path path(filename);
    return (path.parent_path() / ("." + path.filename().string() + ".tmp"))
      .string();
  }

  void
  commit_file(const std::string &temporary, const std::string &filename)
  {
    const int descriptor = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
    if (descriptor < 0 || ::fsync(descriptor) != 0)
      {
        const int error = errno;
        if (descriptor >= 0)
          ::close(descriptor);
        ::unlink(temporary.c_str());
        fail("write", filename, error);
      }
    ::close(descriptor);
    if (::rename(temporary.c_str(), filename.c_str()) != 0)
      {
        const int error = errno;
        ::unlink(temporary.c_str());
        fail("rename a temporary file to", filename, error);
      }
  }

  void
  write_file_atomically(const std::string &filename,
                        const std::string &contents)
  {
    const std::string temporary = temporary_name(filename);
    const int         descriptor =
      ::open(temporary.c_str(),
             O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW,
             0644);
    if (descriptor < 0)
      fail("write", filename, errno);
    if (!write_all(descriptor, contents.data(), contents.size()) ||
        ::fsync(descriptor) != 0)
      {
        const int error = errno;
        ::close(descriptor);
        ::unlink(temporary.c_str());
        fail("write", filename, error);
      }
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
        if (::ftruncate(descriptor, size) == 0)
          {
            ::lseek(descriptor, size, SEEK_SET);
            ::fsync(descriptor);
          }
        fail("write", filename, error);
      }
    size += static_cast<long long>(text.size());
  }

  OutputFolder::OutputFolder(const std::string &directory)
      : directory(directory)
      , lock_descriptor(-1)
  {
    std::error_code error;
    std::filesystem::create_directories(directory, error);
    if (error)
      throw std::runtime_error("cannot create the output folder '" + directory +
                               "': " + error.message());
    // The lock file is also the mark of a folder this program has written
    // in: only there are files with its results' names its own.
    // O_NOFOLLOW: a symbolic link planted under the lock's name would
    // otherwise get its target overwritten with our pid.
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
    // The lock is ours: record our pid for the message above.
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
    // The names VtuWriter, the history and the verdicts use (scheme tags
    // are lower-case letters, digits and hyphens; an MPI run writes each
    // process's piece as solution-<tag>-<step>.<process>.vtu and the
    // .pvtu that lists them), and their temporaries.
    static const std::regex result(
      "(history\\.csv|verdicts\\.csv|"
      "(solution|slave)-[a-z0-9-]+-[0-9]+(\\.[0-9]+)?\\.vtu|"
      "solution-[a-z0-9-]+-[0-9]+\\.pvtu|"
      "(solution|slave)-[a-z0-9-]+\\.pvd)");
    static const std::regex temporary("\\.(.+)\\.tmp");
    std::smatch             match;
    if (std::regex_match(name, match, temporary))
      return std::regex_match(match[1].str(), result);
    return std::regex_match(name, result);
  }

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
