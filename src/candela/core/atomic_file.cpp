#include "candela/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <string>
#include <system_error>

#include "candela/core/error.h"

namespace candela {

namespace fs = std::filesystem;

namespace {

// Unique within the process by the counter and across processes by the pid, so concurrent
// writers of the same destination never share a temporary file.
fs::path temporary_path_for(const fs::path& destination) {
    static std::atomic<unsigned> counter{0};
    const fs::path folder = destination.parent_path();
    // Built by appending: GCC 12's -Wrestrict misfires on `"literal" + std::string` at -O3.
    std::string stem = ".";
    stem += destination.filename().string();
    stem += ".tmp.";
    stem += std::to_string(static_cast<long long>(::getpid()));
    stem += ".";
    for (;;) {
        fs::path candidate = folder / (stem + std::to_string(counter++));
        std::error_code ec;
        if (!fs::exists(candidate, ec)) return candidate;
    }
}

std::string errno_text(int error) { return std::error_code(error, std::generic_category()).message(); }

// Pushes the file's data to the disk before the rename, so that after a power loss the
// destination is never the renamed but still empty file (the rename itself is journaled).
void sync_to_disk(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw std::runtime_error("cannot reopen the written file: " + errno_text(errno));
    const int result = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (result != 0) throw std::runtime_error("cannot flush the file to disk: " + errno_text(error));
}

void remove_quietly(const fs::path& file) {
    std::error_code ec;
    fs::remove(file, ec);
}

SceneError write_error(const fs::path& destination, const std::string& message) {
    SourceLocation where;
    where.file = destination.string();
    return SceneError{std::move(where), "cannot write: " + message};
}

}  // namespace

void write_file_atomically(const fs::path& destination,
                           const std::function<void(const fs::path& temporary)>& write) {
    if (destination.filename().empty())
        throw write_error(destination, "the path names a folder, expected a file name");
    const fs::path folder = destination.parent_path().empty() ? fs::path(".") : destination.parent_path();
    std::error_code ec;
    if (!fs::is_directory(folder, ec))
        throw write_error(destination, "the folder \"" + folder.string() + "\" does not exist");
    if (fs::is_directory(destination, ec))
        throw write_error(destination, "a folder of that name exists");

    const fs::path temporary = temporary_path_for(destination);
    try {
        write(temporary);
        if (!fs::is_regular_file(temporary, ec))
            throw std::runtime_error("the writer produced no file");
        sync_to_disk(temporary);
        fs::rename(temporary, destination);
    } catch (const SceneError&) {
        remove_quietly(temporary);
        throw;
    } catch (const RenderError&) {
        remove_quietly(temporary);
        throw;
    } catch (const fs::filesystem_error& e) {
        remove_quietly(temporary);
        throw write_error(destination, e.code().message());
    } catch (const std::exception& e) {
        remove_quietly(temporary);
        throw write_error(destination, e.what());
    } catch (...) {
        remove_quietly(temporary);
        throw;
    }
}

void write_contents_atomically(const fs::path& destination, std::string_view contents) {
    write_file_atomically(destination, [&](const fs::path& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) throw std::runtime_error("cannot create a temporary file: " + errno_text(errno));
        const size_t written = std::fwrite(contents.data(), 1, contents.size(), file);
        const int write_errno = errno;
        const bool closed = std::fclose(file) == 0;
        if (written != contents.size())
            throw std::runtime_error("write failed: " + errno_text(write_errno));
        if (!closed) throw std::runtime_error("closing the file failed: " + errno_text(errno));
    });
}

}  // namespace candela
