// @sect3{gmsh in a child process}
//
// gmsh_file.cc checks a mesh file and what gmsh made of it; this file is
// where gmsh makes it, out of harm's way. gmsh 4.8's readers end the
// process on some damaged files (a node -1 in an ASCII 4.1 element, a
// damaged binary file: SIGSEGV or SIGABRT), a failed read leaves the
// library "busy" until gmsh::finalize, and gmsh::initialize changes the
// locale and lifts the stack limit of the process that calls it. None of
// that may reach the program: it forks, the child runs gmsh (reads the
// file, or meshes the script) and writes the model into a pipe, and the
// parent reads it back. The answer is a byte of status (0: the model, 1:
// gmsh's message), the data, and a marker that says it is whole; a crash,
// an exit(), a hang past the time limit or a Ctrl-C all end the child, and
// each becomes one line that names the file. The cost is one fork per
// read, a few milliseconds.
#include <ring_contact/base/dimension.h>
#include <ring_contact/base/utilities.h>
#include <ring_contact/input/gmsh_process.h>

#include <fcntl.h>
#include <gmsh.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <sstream>
#include <stdexcept>

namespace RingContact
{
  namespace Geometry
  {
    namespace
    {
      // The same first words as gmsh_file.cc's errors: to the user, the
      // light check, gmsh and the check of its answer are one reader.
      [[noreturn]] void
      fail(const std::string &filename, const std::string &what)
      {
        throw std::runtime_error("cannot read mesh file '" +
                                 printable(filename, 200) + "': " + what);
      }

      // What the child sends: a byte of status, then either gmsh's error
      // message or the model. Values go as their raw bytes: parent and
      // child are one program on one machine (a fork), so byte order and
      // layout are the same on both ends. A vector or a string is its
      // length (64 bits) followed by its elements.
      class Writer
      {
      public:
        explicit Writer(const int fd)
            : fd(fd)
        {}

        template <typename T>
        void
        value(const T &v)
        {
          bytes(&v, sizeof(T));
        }

        template <typename T>
        void
        vector(const std::vector<T> &v)
        {
          value<std::uint64_t>(v.size());
          bytes(v.data(), v.size() * sizeof(T));
        }

        void
        string(const std::string &s)
        {
          value<std::uint64_t>(s.size());
          bytes(s.data(), s.size());
        }

        // write() may take less than it is given (a signal in the middle
        // of a large write), or be interrupted before it takes anything;
        // the model may be many megabytes, far beyond what the pipe holds
        // while the parent reads. A write that fails ends the child (exit
        // code 3): it has no one left to tell, and the parent reports the
        // incomplete answer or the code. _exit(), not exit(): the child
        // must not run the program's atexit handlers or flush buffers it
        // inherited.
        void
        bytes(const void *data, std::size_t n)
        {
          const char *p = static_cast<const char *>(data);
          while (n > 0)
            {
              const ssize_t written = ::write(fd, p, n);
              if (written < 0 && errno == EINTR)
                continue;
              if (written <= 0)
                _exit(3);
              p += written;
              n -= static_cast<std::size_t>(written);
            }
        }

      private:
        const int fd;
      };

      // The parent's side: every length is checked against what remains of
      // the answer before anything is read or allocated, so that a child
      // that died in the middle of its answer (or wrote garbage) gives the
      // error "incomplete", not a read past the end or a huge allocation.
      class Reader
      {
      public:
        Reader(const std::string &data, const std::string &filename)
            : data(data)
            , filename(filename)
        {}

        template <typename T>
        T
        value()
        {
          T v;
          bytes(&v, sizeof(T));
          return v;
        }

        template <typename T>
        std::vector<T>
        vector()
        {
          // Divided rather than multiplied: n * sizeof(T) may overflow.
          const auto n = value<std::uint64_t>();
          if (n > (data.size() - at) / sizeof(T))
            incomplete();
          std::vector<T> v(n);
          bytes(v.data(), n * sizeof(T));
          return v;
        }

        std::string
        string()
        {
          const auto n = value<std::uint64_t>();
          if (n > data.size() - at)
            incomplete();
          std::string s = data.substr(at, n);
          at += n;
          return s;
        }

        bool
        at_end() const
        {
          return at == data.size();
        }

        /// Whether the next byte is `marker` (false at the end).
        bool
        next_is(const std::uint8_t marker) const
        {
          return at < data.size() &&
                 static_cast<std::uint8_t>(data[at]) == marker;
        }

      private:
        const std::string &data;
        const std::string &filename;
        std::size_t        at = 0;

        // memcpy, not a cast: the answer's bytes have no alignment.
        void
        bytes(void *to, const std::size_t n)
        {
          if (n > data.size() - at)
            incomplete();
          if (n > 0)
            std::memcpy(to, data.data() + at, n);
          at += n;
        }

        [[noreturn]] void
        incomplete() const
        {
          fail(filename, "the answer of gmsh's reader is incomplete");
        }
      };

      // The last four bytes of every answer ("RING" in ASCII): an answer
      // that ends without them was cut short, one with bytes after them is
      // not what the child meant to write.
      constexpr std::uint32_t end_of_answer = 0x52494e47;

      // Before the answer, the child says what it starts: this byte and a
      // string ("reading it", "meshing it with Mesh.Algorithm = 8 (...)").
      // A child that crashes has said what it was doing: a crash of gmsh's
      // mesher is then reported as gmsh's, with the algorithm, not as a
      // damaged file (Mesh.Algorithm = 8 crashes gmsh 4.8 on a unit
      // square).
      constexpr std::uint8_t stage_marker = 0xfe;

      // The points per curve of a script's model (see gmsh_child()), and
      // per parameter direction of a surface of a 3D one.
      constexpr unsigned int curve_samples   = 513;
      constexpr unsigned int surface_samples = 17;

      // The last stage the child announced in a (possibly cut) answer, ""
      // if none.
      std::string
      last_stage(const std::string &answer, const std::string &filename)
      {
        std::string stage;
        Reader      in(answer, filename);
        try
          {
            while (in.next_is(stage_marker))
              {
                in.value<std::uint8_t>();
                stage = in.string();
              }
          }
        catch (const std::exception &)
          {
            // A stage cut in the middle: the one before it.
          }
        return stage;
      }

      // gmsh's names of its 2d algorithms (Mesh.Algorithm).
      std::string
      algorithm_name(const int algorithm)
      {
        switch (algorithm)
          {
            case 1:
              return "MeshAdapt";
            case 2:
              return "Automatic";
            case 3:
              return "Initial mesh only";
            case 5:
              return "Delaunay";
            case 6:
              return "Frontal-Delaunay";
            case 7:
              return "BAMG";
            case 8:
              return "Frontal-Delaunay for quads";
            case 9:
              return "Packing of parallelograms";
            case 11:
              return "Quasi-structured quad";
            default:
              return "unknown";
          }
      }

      // gmsh 4.8 throws some of its errors (a surface that the transfinite
      // algorithm cannot mesh, say) from where no exception can leave:
      // std::terminate() is called. The child then answers with gmsh's
      // last error, so that the user reads what gmsh said, not that it
      // crashed. (Found when gmsh's Rotate merged the coincident points of
      // two blocks.) A terminate handler takes no arguments: the pipe's
      // descriptor is a global of the child.
      int answer_fd = -1;

      [[noreturn]] void
      answer_last_error()
      {
        // gmsh is in whatever state made it terminate: asking it for its
        // message may throw too, and then the answer says so in general.
        std::string message;
        try
          {
            gmsh::logger::getLastError(message);
          }
        catch (...)
          {}
        if (message.empty())
          message = "gmsh stopped without a message (std::terminate)";
        Writer out(answer_fd);
        out.value<std::uint8_t>(1);
        out.string(message);
        out.value(end_of_answer);
        _exit(0);
      }

      // The status byte of a model (0), then a script's Mesh.ScalingFactor
      // as the script left it (1 for a mesh file): gmsh applies it only
      // when it saves a mesh, so the model the child sends (nodes and
      // curves) is unscaled; the parent scales both (scale_model()).
      void
      begin_model(Writer &out, const bool geo)
      {
        double factor = 1;
        if (geo)
          gmsh::option::getNumber("Mesh.ScalingFactor", factor);
        out.value<std::uint8_t>(0);
        out.value(factor);
      }

      // gmsh started in the child, as by its command line.
      void
      start_gmsh(const GeoNumbers &geo_numbers)
      {
        // A script's numbers (Mesh/Geo parameters) as gmsh's command
        // line `-setnumber name value`: gmsh 4.8's API has no other way
        // to reach a script's DefineConstant[]. %.17g writes a double
        // that reads back to the same bits.
        std::vector<std::string> arguments = {"gmsh"};
        for (const auto &[name, value] : geo_numbers)
          {
            char number[64];
            std::snprintf(number, sizeof(number), "%.17g", value);
            arguments.insert(arguments.end(), {"-setnumber", name, number});
          }
        std::vector<char *> argv;
        for (auto &argument : arguments)
          argv.push_back(argument.data());
        argv.push_back(nullptr);
        // No configuration file: a user's gmshrc must not change how a
        // mesh is read. Quiet, errors thrown (not printed, not exit()),
        // and one thread: under MPI every core has a process already.
        gmsh::initialize(static_cast<int>(arguments.size()),
                         argv.data(),
                         /*readConfigFiles=*/false);
        gmsh::option::setNumber("General.Terminal", 0);
        gmsh::option::setNumber("General.AbortOnError", 3); // throw
        gmsh::option::setNumber("General.NumThreads", 1);
      }

      // Per entity of the model its dimension, tag, physical groups and
      // elements by type: the parent checks and assembles them.
      void
      write_entities(Writer &out, const gmsh::vectorpair &entities)
      {
        for (const auto &[entity_dim, tag] : entities)
          {
            std::vector<int> physicals;
            gmsh::model::getPhysicalGroupsForEntity(entity_dim, tag, physicals);
            std::vector<int>                      types;
            std::vector<std::vector<std::size_t>> element_tags, nodes;
            gmsh::model::mesh::getElements(
              types, element_tags, nodes, entity_dim, tag);
            out.value<std::int32_t>(entity_dim);
            out.value<std::int32_t>(tag);
            out.vector(physicals);
            out.vector(types);
            for (unsigned int t = 0; t < types.size(); ++t)
              {
                out.vector(element_tags[t]);
                out.vector(nodes[t]);
              }
          }
      }

      // The curves of a script's model, sampled for the parent.
      void
      write_curves(Writer &out, const gmsh::vectorpair &entities)
      {
        // A script's curves as the CAD kernel has them: each sampled at
        // `curve_samples` points evenly spaced in its parameter
        // (gmsh::model::getValue), from which the parent recognises a
        // straight line or a circle and otherwise interpolates
        // (model_curves.cc): the geometry that refinement and a curved
        // mapping follow. A mesh file has no CAD: none.
        std::vector<std::pair<int, std::vector<double>>> curves;
        for (const auto &[entity_dim, tag] : entities)
          if (entity_dim == 1)
            // A curve the kernel cannot evaluate (a discrete or
            // compound curve) stays straight-sided: the status byte
            // has gone out, and an error now would lose the mesh.
            try
              {
                std::vector<double> low, high;
                gmsh::model::getParametrizationBounds(1, tag, low, high);
                if (low.size() != 1 || high.size() != 1 ||
                    !std::isfinite(low[0]) || !std::isfinite(high[0]) ||
                    !(high[0] > low[0]))
                  continue;
                std::vector<double> t(curve_samples), xyz;
                for (unsigned int i = 0; i < curve_samples; ++i)
                  t[i] =
                    low[0] + (high[0] - low[0]) * i / (curve_samples - 1.0);
                gmsh::model::getValue(1, tag, t, xyz);
                if (xyz.size() == 3 * curve_samples &&
                    std::all_of(xyz.begin(), xyz.end(), [](double v) {
                      return std::isfinite(v);
                    }))
                  curves.emplace_back(tag, std::move(xyz));
              }
            catch (...)
              {}
        out.value<std::uint64_t>(curves.size());
        for (const auto &[tag, xyz] : curves)
          {
            out.value<std::int32_t>(tag);
            out.vector(xyz);
          }
      }

      // The surfaces of a script's 3D model, sampled for the parent: each
      // at surface_samples^2 points of a grid evenly spaced in its two
      // parameters, with the CAD kernel's unit normal there
      // (gmsh::model::getNormal), from which the parent recognises a
      // plane, a sphere or a cylinder (model_surfaces.cc). As for the
      // curves, a surface the kernel cannot evaluate is left out.
      void
      write_surfaces(Writer &out, const gmsh::vectorpair &entities)
      {
        constexpr unsigned int                           n = surface_samples;
        std::vector<std::pair<int, std::vector<double>>> surfaces;
        const auto finite = [](const std::vector<double> &v) {
          return std::all_of(v.begin(), v.end(), [](double x) {
            return std::isfinite(x);
          });
        };
        for (const auto &[entity_dim, tag] : entities)
          if (entity_dim == 2)
            try
              {
                std::vector<double> low, high;
                gmsh::model::getParametrizationBounds(2, tag, low, high);
                if (low.size() != 2 || high.size() != 2 || !finite(low) ||
                    !finite(high) || !(high[0] > low[0]) || !(high[1] > low[1]))
                  continue;
                std::vector<double> uv, xyz, normals;
                for (unsigned int i = 0; i < n; ++i)
                  for (unsigned int j = 0; j < n; ++j)
                    uv.insert(uv.end(),
                              {low[0] + (high[0] - low[0]) * i / (n - 1.0),
                               low[1] + (high[1] - low[1]) * j / (n - 1.0)});
                gmsh::model::getValue(2, tag, uv, xyz);
                gmsh::model::getNormal(tag, uv, normals);
                // At a degenerate point of the parametrization (a sphere's
                // pole) the normal may be undefined: sent as zero, which
                // the parent's fits ignore (only a cylinder's uses them).
                for (double &component : normals)
                  if (!std::isfinite(component))
                    component = 0;
                if (xyz.size() == 3 * n * n && normals.size() == 3 * n * n &&
                    finite(xyz))
                  {
                    xyz.insert(xyz.end(), normals.begin(), normals.end());
                    surfaces.emplace_back(tag, std::move(xyz));
                  }
              }
            catch (...)
              {}
        out.value<std::uint64_t>(surfaces.size());
        for (const auto &[tag, values] : surfaces)
          {
            out.value<std::int32_t>(tag);
            out.vector(values);
          }
      }

      // The child: gmsh reads (or meshes) the file and the model is
      // written to `fd`. Never returns.
      [[noreturn]] void
      gmsh_child(const int          fd,
                 const std::string &filename,
                 const bool         geo,
                 const GeoNumbers  &geo_numbers,
                 const unsigned int element_order)
      {
        Writer out(fd);
        answer_fd = fd;
        std::set_terminate(answer_last_error);
        try
          {
            start_gmsh(geo_numbers);
            const auto stage = [&out](const std::string &what) {
              out.value<std::uint8_t>(stage_marker);
              out.string(what);
            };
            stage("reading it");
            gmsh::open(filename);
            // A script is meshed here, in the model's dimension (3 for a
            // model of volumes, 2 otherwise), at the order the caller asks:
            // the rings 2 as soon as one of them is quadratic, so that the
            // mid-side nodes are gmsh's, on its circles; a general problem
            // 1, since its cells take the vertices only.
            if (geo)
              {
                double algorithm = 0;
                gmsh::option::getNumber("Mesh.Algorithm", algorithm);
                const int a = static_cast<int>(algorithm);
                stage("meshing it with Mesh.Algorithm = " + std::to_string(a) +
                      " (" + algorithm_name(a) + ")");
                gmsh::model::mesh::generate(
                  std::max(2, gmsh::model::getDimension()));
                stage("making its elements of order " +
                      std::to_string(element_order));
                gmsh::model::mesh::setOrder(static_cast<int>(element_order));
              }

            // Every node of the model (all dimensions and entities), with
            // its coordinates but no parametric ones. Then per entity its
            // physical groups and its elements by type: the parent checks
            // and assembles them, so the child does nothing but ask gmsh.
            std::vector<std::size_t> node_tags;
            std::vector<double>      coordinates, parametric;
            gmsh::model::mesh::getNodes(
              node_tags, coordinates, parametric, -1, -1, false, false);
            gmsh::vectorpair entities;
            gmsh::model::getEntities(entities);

            // The status byte goes out once the nodes and the entities are
            // known. An error in the per-entity questions below would come
            // after part of the model: the parent then finds the answer
            // incomplete or inconsistent, an error still, but without
            // gmsh's words.
            begin_model(out, geo);
            out.vector(node_tags);
            out.vector(coordinates);
            out.value<std::uint64_t>(entities.size());
            write_entities(out, entities);
            // A mesh file has no CAD: no curves (their count, 0, is sent).
            write_curves(out, geo ? entities : gmsh::vectorpair());
            // A 3D script's surfaces too (a 2D model's are its planes).
            write_surfaces(out,
                           geo && gmsh::model::getDimension() == 3 ?
                             entities :
                             gmsh::vectorpair());
            out.value(end_of_answer);
            _exit(0);
          }
        catch (const std::string &message) // what gmsh 4.8 throws
          {
            out.value<std::uint8_t>(1);
            out.string(message);
          }
        // The memory cap of prepare_child() turns a runaway allocation
        // into this, and into a message rather than a crash.
        catch (const std::bad_alloc &)
          {
            out.value<std::uint8_t>(1);
            out.string("out of memory");
          }
        catch (const std::exception &e)
          {
            out.value<std::uint8_t>(1);
            out.string(e.what());
          }
        catch (...)
          {
            out.value<std::uint8_t>(1);
            out.string("an unknown exception");
          }
        out.value(end_of_answer);
        _exit(0);
      }

      // Run gmsh_child() in a child process and return its answer. A
      // crash, an exit or a hang of gmsh becomes a one-line error.
      // In the child, before gmsh runs: quiet (gmsh's messages go nowhere,
      // the error comes back through the pipe, which becomes descriptor 3),
      // no file of the program held open (the results folder's lock),
      // killed with the program, deaf to the Ctrl-C meant for the program
      // (which stops between steps), and bounded in memory.
      void
      prepare_child(const int pipe_end, const pid_t parent)
      {
        // gmsh's output, and whatever a script prints, go to /dev/null: the
        // program's terminal and log get nothing from the child.
        const int quiet = open("/dev/null", O_RDWR);
        if (quiet >= 0)
          {
            dup2(quiet, 0);
            dup2(quiet, 1);
            dup2(quiet, 2);
          }
        // The pipe at a known place, every other descriptor closed: a
        // child that hangs must not hold the results folder's lock (flock)
        // or any other file or socket of the program.
        if (dup2(pipe_end, 3) != 3)
          _exit(4);
        closefrom(4);
        // Killed when the program dies. If it died between fork() and
        // prctl(), the signal will never come: the child is now someone
        // else's and leaves at once.
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        if (getppid() != parent)
          _exit(5);
        // Ctrl-C reaches the whole process group; the parent decides what
        // it means (fork_gmsh() kills the child at once). A write into a
        // pipe the parent has closed ends the child, whatever disposition
        // of SIGPIPE it inherited.
        signal(SIGINT, SIG_IGN);
        signal(SIGTERM, SIG_IGN);
        signal(SIGPIPE, SIG_DFL);
        // A fault of gmsh's ends the child by gmsh's own signal, which the
        // parent names. A sanitizer build's handlers would turn it into
        // an abort (SIGABRT) and the message would name the wrong signal.
        for (const int fault : {SIGSEGV, SIGBUS, SIGFPE, SIGILL})
          signal(fault, SIG_DFL);
#ifndef __SANITIZE_ADDRESS__
        // (Not under AddressSanitizer: its shadow memory already holds
        // terabytes of address space.)
        // The address space capped at the machine's physical memory: a
        // damaged count that makes gmsh allocate without bound fails its
        // allocation instead of driving the machine into swap. A lower
        // limit set by the user stays.
        const double memory =
          static_cast<double>(sysconf(_SC_PHYS_PAGES)) * sysconf(_SC_PAGE_SIZE);
        rlimit limit;
        if (memory > 0 && getrlimit(RLIMIT_AS, &limit) == 0)
          {
            const rlim_t cap = static_cast<rlim_t>(memory);
            if (limit.rlim_cur == RLIM_INFINITY || limit.rlim_cur > cap)
              {
                limit.rlim_cur = cap;
                setrlimit(RLIMIT_AS, &limit);
              }
          }
#endif
      }

      // The child's answer, read from `fd` until the child closes it, while
      // watching the clock (`timed_out` past the limit, if any) and the stop
      // flag (`interrupted`): both end the wait at once.
      std::string
      read_answer(const int    fd,
                  const double time_limit_seconds,
                  bool        &timed_out,
                  bool        &interrupted)
      {
        std::string answer;
        const auto  start = std::chrono::steady_clock::now();
        char        buffer[1 << 16];
        while (true)
          {
            const double elapsed = std::chrono::duration<double>(
                                     std::chrono::steady_clock::now() - start)
                                     .count();
            if (time_limit_seconds > 0 && elapsed > time_limit_seconds)
              {
                timed_out = true;
                break;
              }
            // Ctrl-C: gmsh (deaf to it) is stopped here, at once, not
            // when a script that may never end has been meshed.
            if (stop_signal.load() != 0)
              {
                interrupted = true;
                break;
              }
            // At most 200 ms of waiting between looks at the clock and the
            // stop flag: the limit and a Ctrl-C act within a fifth of a
            // second, and an idle wait costs nothing.
            pollfd    wait_for{fd, POLLIN, 0};
            const int ready = poll(&wait_for, 1, 200);
            if (ready < 0 && errno != EINTR)
              break;
            if (ready <= 0)
              continue;
            // 0: the child closed the pipe (it ended); an error other than
            // an interruption ends the wait too, and the child's status
            // below says what happened.
            const ssize_t n = read(fd, buffer, sizeof(buffer));
            if (n < 0 && (errno == EINTR || errno == EAGAIN))
              continue;
            if (n <= 0)
              break;
            answer.append(buffer, static_cast<std::size_t>(n));
          }
        return answer;
      }

      // The parent's side of the fork: start the child, gather its answer
      // while watching the clock and the stop flag, and turn the way the
      // child ended into a message. The answer is only returned when the
      // child ended by itself with code 0; run_gmsh() then parses it.
      std::string
      fork_gmsh(const std::string &filename,
                const bool         geo,
                const GeoNumbers  &geo_numbers,
                const unsigned int element_order,
                const double       time_limit_seconds)
      {
        // Close-on-exec: no other child the program may start inherits the
        // pipe (the child's own copy at descriptor 3 is made by dup2(),
        // which clears the flag).
        int ends[2];
        if (pipe2(ends, O_CLOEXEC) != 0)
          fail(filename,
               "cannot make a pipe for gmsh: " + std::string(strerror(errno)));
        // Nothing buffered may be written twice, by the child too.
        std::cout.flush();
        std::cerr.flush();
        std::fflush(nullptr);
        const pid_t parent = getpid();
        const pid_t pid    = fork();
        if (pid < 0)
          {
            const int error = errno;
            close(ends[0]);
            close(ends[1]);
            fail(filename,
                 "cannot start a process for gmsh: " +
                   std::string(strerror(error)));
          }
        if (pid == 0)
          {
            prepare_child(ends[1], parent);
            gmsh_child(3, filename, geo, geo_numbers, element_order);
          }
        // The parent keeps no write end: read() sees the end of the file
        // when the child has closed its own, by ending.
        close(ends[1]);

        bool              timed_out = false, interrupted = false;
        const std::string answer =
          read_answer(ends[0], time_limit_seconds, timed_out, interrupted);
        // The child is always waited for, killed or not: no zombie is left,
        // and its status is known before anything is reported.
        close(ends[0]);
        if (timed_out || interrupted)
          kill(pid, SIGKILL);
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR)
          ;
        // Not a mesh error: the run ends as a signal asks (exit 130 or
        // 143), saying that nothing was written. Before this, gmsh's child,
        // deaf to the signal, held a never-ending script's run until a
        // second signal killed it without a message.
        if (interrupted)
          throw Interrupted("while gmsh read or meshed '" + filename + "'");
        if (timed_out)
          fail(filename,
               "gmsh did not finish reading it within " +
                 std::to_string(static_cast<int>(time_limit_seconds)) + " s");
        // A crash while gmsh meshes a script is gmsh's: the script was read.
        // While it reads a file, the file is the suspect (gmsh 4.8 crashes
        // on some damaged files).
        if (WIFSIGNALED(status))
          {
            const std::string signal = "signal " +
                                       std::to_string(WTERMSIG(status)) + ", " +
                                       strsignal(WTERMSIG(status));
            const std::string stage = last_stage(answer, filename);
            if (stage.rfind("meshing", 0) == 0 || stage.rfind("making", 0) == 0)
              fail(filename,
                   "gmsh " GMSH_API_VERSION " crashed (" + signal + ") while " +
                     stage +
                     ": a fault of gmsh's mesher, not of the script; another "
                     "algorithm may mesh it (Mesh.Algorithm = 6, "
                     "Frontal-Delaunay, with Recombine Surface)");
            fail(filename,
                 "gmsh's reader crashed on it (" + signal +
                   "): the file is damaged or not a mesh gmsh can read");
          }
        // The child's own codes (3: the pipe, 4: descriptor 3, 5: the
        // parent gone) or an exit() inside gmsh.
        if (WIFEXITED(status) && WEXITSTATUS(status) != 0)
          fail(filename,
               "gmsh's reader stopped (exit code " +
                 std::to_string(WEXITSTATUS(status)) + ") on it");
        return answer;
      }

      // Mesh.ScalingFactor of a script: `gmsh -2` saves the mesh scaled by
      // it (a model drawn in millimetres with 0.001 is saved in metres),
      // while the model gmsh holds, which the child sends, is not. Ignored,
      // the program ran the unscaled model, a thousand times too large.
      // The nodes and the sampled curves are scaled alike, so that the
      // curves stay the geometry of the faces (model_curves.cc). A factor
      // that is not a positive number would make no body: refused.
      void
      scale_model(GmshModel         &model,
                  const double       scaling_factor,
                  const std::string &filename)
      {
        if (scaling_factor == 1)
          return;
        if (!(scaling_factor > 0) || !std::isfinite(scaling_factor))
          {
            std::ostringstream value;
            value << scaling_factor;
            fail(filename,
                 "its Mesh.ScalingFactor is " + value.str() +
                   ": the mesh gmsh would save is then no body (a positive "
                   "factor scales the model, e.g. 0.001 from millimetres "
                   "to metres)");
          }
        for (double &x : model.coordinates)
          x *= scaling_factor;
        for (auto &curve : model.curves)
          for (double &x : curve.second)
            x *= scaling_factor;
        // A surface's points, not its unit normals (the second half).
        for (auto &surface : model.surfaces)
          for (std::size_t i = 0; i < surface.second.size() / 2; ++i)
            surface.second[i] *= scaling_factor;
      }
    } // namespace

    // @sect4{The model, read back}
    //
    // The answer parsed in the order the child wrote it. The last test
    // holds the answer to itself: its end marker, nothing after it, and
    // three coordinates per node (gmsh gives z too; gmsh_file.cc checks
    // that it is zero).
    GmshModel
    run_gmsh(const std::string &filename,
             const bool         mesh_script,
             const GeoNumbers  &geo_numbers,
             const unsigned int element_order,
             const double       time_limit_seconds)
    {
      const std::string answer = fork_gmsh(
        filename, mesh_script, geo_numbers, element_order, time_limit_seconds);
      Reader in(answer, filename);
      if (answer.empty())
        fail(filename, "gmsh's reader gave no answer");
      while (in.next_is(stage_marker))
        {
          in.value<std::uint8_t>();
          in.string();
        }
      if (in.value<std::uint8_t>() != 0)
        // gmsh's message (it often repeats the file name), on one line.
        fail(filename, "gmsh: " + printable(in.string(), 300));
      GmshModel    model;
      const double scaling_factor = in.value<double>();
      model.node_tags             = in.vector<std::size_t>();
      model.coordinates           = in.vector<double>();
      const auto n_entities       = in.value<std::uint64_t>();
      for (std::uint64_t e = 0; e < n_entities; ++e)
        {
          GmshModel::Entity entity;
          entity.dim       = in.value<std::int32_t>();
          entity.tag       = in.value<std::int32_t>();
          entity.physicals = in.vector<int>();
          entity.types     = in.vector<int>();
          for (unsigned int t = 0; t < entity.types.size(); ++t)
            {
              entity.element_tags.push_back(in.vector<std::size_t>());
              entity.element_nodes.push_back(in.vector<std::size_t>());
            }
          model.entities.push_back(std::move(entity));
        }
      const auto n_curves = in.value<std::uint64_t>();
      for (std::uint64_t c = 0; c < n_curves; ++c)
        {
          const int tag = in.value<std::int32_t>();
          model.curves.emplace_back(tag, in.vector<double>());
          if (model.curves.back().second.size() != 3 * curve_samples)
            fail(filename, "the answer of gmsh's reader is inconsistent");
        }
      const auto n_surfaces = in.value<std::uint64_t>();
      for (std::uint64_t s = 0; s < n_surfaces; ++s)
        {
          const int tag = in.value<std::int32_t>();
          model.surfaces.emplace_back(tag, in.vector<double>());
          if (model.surfaces.back().second.size() !=
              6 * surface_samples * surface_samples)
            fail(filename, "the answer of gmsh's reader is inconsistent");
        }
      if (in.value<std::uint32_t>() != end_of_answer || !in.at_end() ||
          model.coordinates.size() != 3 * model.node_tags.size())
        fail(filename, "the answer of gmsh's reader is inconsistent");
      scale_model(model, scaling_factor, filename);
      return model;
    }
  } // namespace Geometry
} // namespace RingContact
