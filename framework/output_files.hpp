#pragma once
// Output files complete or absent: every file pride writes for the user (exports, figures, report
// pages, pictures) is written through an OutputFiles, so a full disk, a write error or any failure
// on the way leaves nothing behind. Each file is written to a temporary name beside its own
// (hidden: ".NAME.pride-PID-N.tmp", so the rename stays within one file system), synced, and all
// are renamed into place by commit() only when every one of them was written; until then, and when
// it fails, discard() (also the destructor) removes the temporary files and the folders this
// output made. A rename writes no data, so a full disk cannot stop a commit half-way; should a
// rename fail all the same, the files renamed before it are put back (a file it replaced is kept
// under a hard link until the end). Devices, pipes and other files that are not regular
// (/dev/stdout, /dev/null) are written directly: renaming over them would replace them. The
// reading counterpart is framework/read_file.hpp.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "framework/error.hpp"

namespace pride {

class OutputFiles {
  public:
    /// One file being written: to its temporary name, or directly when it is a device or a pipe.
    class File {
      public:
        File(const File&) = delete;
        File& operator=(const File&) = delete;
        ~File() {
            if (fd_ >= 0) ::close(fd_);
        }

        /// Appends `size` bytes; false when they cannot be written (the first reason is kept for
        /// close()). Never throws, for C libraries' write callbacks (cairo's streams).
        bool append(const void* data, std::size_t size) noexcept {
            if (error_ != 0) return false;
            if (fd_ < 0) return fail_with(EBADF);
            const char* p = static_cast<const char*>(data);
            while (size > 0) {
                const ssize_t n = ::write(fd_, p, size);
                if (n < 0 && errno == EINTR) continue;
                if (n <= 0) return fail_with(n < 0 ? errno : EIO);
                p += n;
                size -= static_cast<std::size_t>(n);
            }
            return true;
        }
        /// Appends `text`; InputError "PATH: cannot write: REASON" when it cannot.
        void write(std::string_view text) {
            if (!append(text.data(), text.size())) throw error();
        }
        /// The last step of writing it: synced to the disk (a delayed write error, a quota, shows
        /// here) and closed. InputError "PATH: cannot write: REASON" for the first failure of the
        /// file. Closed files stay where they are until OutputFiles::commit().
        void close() {
            if (fd_ < 0) {
                if (error_ != 0) throw error();
                return;
            }
            if (error_ == 0 && !direct_ && ::fsync(fd_) != 0) fail_with(errno);
            if (::close(fd_) != 0 && error_ == 0 && errno != EINTR) fail_with(errno);
            fd_ = -1;
            if (error_ != 0) throw error();
        }
        /// The final name (messages name it, never the temporary one).
        const std::string& path() const { return path_; }
        /// Where the bytes go now: the temporary name, or the path itself when written directly.
        const std::string& written_at() const { return temporary_.empty() ? path_ : temporary_; }
        /// The first failure as the error to throw.
        InputError error() const {
            return InputError(path_ + ": cannot write: " + std::strerror(error_ != 0 ? error_ : EIO));
        }

      private:
        friend class OutputFiles;
        File() = default;
        bool fail_with(int e) noexcept {
            if (error_ == 0) error_ = e != 0 ? e : EIO;
            return false;
        }
        std::string path_;       // as named, for messages
        std::string key_;        // path_ resolved: no two files of an output share one
        std::string final_;      // where it goes: path_, or the file a symbolic link names
        std::string temporary_;  // empty: written directly, or renamed into place
        std::string backup_;     // the replaced file's hard link during commit()
        bool direct_ = false;
        int fd_ = -1, error_ = 0;
    };

    OutputFiles() = default;
    OutputFiles(const OutputFiles&) = delete;
    OutputFiles& operator=(const OutputFiles&) = delete;
    ~OutputFiles() { discard(); }

    /// The folder a command writes its files into, as the user named it (a link there is
    /// followed), made if need be. Inside it this output writes only through what it finds or
    /// makes there itself: a symbolic link in the place of one of its files is replaced by the
    /// file, never followed, and a link in the place of a folder it writes into is refused, so a
    /// link planted in a shared folder cannot send the output elsewhere.
    void output_folder(const std::filesystem::path& folder) {
        make_folder(folder);
        roots_.push_back(folder.lexically_normal());
    }

    /// Makes `folder` and its missing parents for the files of this output; those it made are
    /// removed again by discard(). InputError "PATH: exists and is not a folder", "PATH: cannot
    /// create the folder: REASON" or, inside an output_folder(), "PATH: is a symbolic link ...".
    void make_folder(const std::filesystem::path& folder) {
        namespace fs = std::filesystem;
        refuse_links_inside(folder);
        std::vector<fs::path> missing;
        for (fs::path p = folder.lexically_normal(); !p.empty(); p = p.parent_path()) {
            if (p.filename().empty() && p.has_relative_path()) continue;  // "dir/" names "dir"
            struct stat st {};
            if (::stat(p.c_str(), &st) == 0) {
                if (!S_ISDIR(st.st_mode)) throw InputError(p.string() + ": exists and is not a folder");
                break;
            }
            if (const int e = errno; e != ENOENT)
                throw InputError(p.string() + ": cannot create the folder: " + std::strerror(e));
            missing.push_back(p);
            if (p == p.parent_path()) break;
        }
        for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
            if (::mkdir(it->c_str(), 0777) != 0 && errno != EEXIST) {
                const int e = errno;
                throw InputError(it->string() + ": cannot create the folder: " + std::strerror(e));
            }
            made_.push_back(*it);
        }
    }

    /// A new file that becomes `path` at commit(). Its folder must exist (make_folder() makes those
    /// an output owns; a picture's folder is the user's). InputError when `path` is a folder, is
    /// named twice in this output, or its temporary cannot be created (no such folder, no right).
    File& create(const std::filesystem::path& path) {
        File& f = add(path);
        f.fd_ = f.direct_ ? ::open(f.path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666)
                          : ::open(f.temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (f.fd_ < 0) {
            const int e = errno;
            const std::string shown = f.path_;
            names_.erase(f.key_);  // not made: not part of the output
            files_.pop_back();
            throw InputError(shown + ": cannot write: " + std::strerror(e));
        }
        return f;
    }

    /// Whether `path` is written in place rather than renamed into place: a device, a pipe or
    /// another file that is not regular (renaming over it would replace it), or a dangling
    /// symbolic link. A link to a regular file is followed: that file is replaced, the link kept.
    static bool writes_directly(const std::filesystem::path& path) {
        struct stat st {};
        if (::stat(path.c_str(), &st) == 0) return !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
        return ::lstat(path.c_str(), &st) == 0 && S_ISLNK(st.st_mode);
    }

    /// Writes `text` as the whole of `path` (at commit()).
    void write(const std::filesystem::path& path, std::string_view text) {
        File& f = create(path);
        f.write(text);
        f.close();
    }

    /// A new empty folder inside `near` (made if need be) for files that another writer (a child
    /// process) makes and adopt() then takes in; removed with everything in it at the end.
    std::filesystem::path scratch_folder(const std::filesystem::path& near) {
        make_folder(near);
        const std::string name = temporary_name(near / "scratch", "tmp");
        if (::mkdir(name.c_str(), 0777) != 0) {
            const int e = errno;
            throw InputError(near.string() + ": cannot write into the folder: " + std::strerror(e));
        }
        scratch_.emplace_back(name);
        return name;
    }

    /// `written` (complete, in a scratch folder on the file system of `path`) becomes `path` at
    /// commit(), as a file made by create() does; synced here.
    void adopt(const std::filesystem::path& written, const std::filesystem::path& path) {
        File& f = add(path);
        if (f.direct_) throw InputError(f.path_ + ": cannot write: not a regular file");
        f.temporary_ = written.string();
        const int fd = ::open(f.temporary_.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0 || ::fsync(fd) != 0) {
            const int e = errno;
            if (fd >= 0) ::close(fd);
            throw InputError(f.path_ + ": cannot write: " + std::strerror(e));
        }
        ::close(fd);
    }

    /// Every file into place, in the order they were created (so a page's index can come last).
    /// InputError naming the file that could not be closed or renamed; then nothing of this output
    /// is left (discard()).
    void commit() {
        for (auto& f : files_) f->close();
        std::size_t done = 0;
        try {
            for (; done < files_.size(); ++done) {
                File& f = *files_[done];
                if (f.direct_) continue;
                struct stat st {};
                if (::lstat(f.final_.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
                    const std::string backup = temporary_name(f.final_, "old");
                    if (::link(f.final_.c_str(), backup.c_str()) == 0) f.backup_ = backup;
                }
                if (::rename(f.temporary_.c_str(), f.final_.c_str()) != 0) {
                    const int e = errno;
                    throw InputError(f.path_ + ": cannot write: " + std::strerror(e));
                }
                f.temporary_.clear();
            }
        } catch (...) {
            for (std::size_t k = done; k-- > 0;) {  // back as it was
                File& f = *files_[k];
                if (f.direct_) continue;
                if (!f.backup_.empty() ? ::rename(f.backup_.c_str(), f.final_.c_str()) == 0
                                       : ::unlink(f.final_.c_str()) == 0)
                    f.backup_.clear();
            }
            discard();
            throw;
        }
        for (auto& f : files_)
            if (!f->backup_.empty()) ::unlink(f->backup_.c_str());
        files_.clear();
        names_.clear();
        made_.clear();  // they hold the output now
        remove_scratch();
    }

    /// Removes what this output wrote (the direct writes to devices excepted) and the folders it
    /// made; nothing when it was committed. Never throws.
    void discard() noexcept {
        for (auto& f : files_) {
            if (f->fd_ >= 0) ::close(f->fd_);
            f->fd_ = -1;
            if (!f->direct_ && !f->temporary_.empty()) ::unlink(f->temporary_.c_str());
            if (!f->backup_.empty()) ::unlink(f->backup_.c_str());
        }
        files_.clear();
        names_.clear();
        remove_scratch();
        for (auto it = made_.rbegin(); it != made_.rend(); ++it) ::rmdir(it->c_str());  // only when empty
        made_.clear();
    }

  private:
    /// The entry of a file to be written as `path`: checked, its folder made, its temporary named.
    File& add(const std::filesystem::path& path) {
        namespace fs = std::filesystem;
        const std::string shown = path.string();
        const bool inside = refuse_links_inside(path.parent_path());
        struct stat st {};
        const bool exists = inside ? ::lstat(path.c_str(), &st) == 0 : ::stat(path.c_str(), &st) == 0;
        if (path.filename().empty() || (exists && S_ISDIR(st.st_mode)))
            throw InputError(shown + ": cannot write: it is a folder");
        // Inside an output folder a link in a file's place is replaced, never followed: files are
        // told apart by their names in the folder (two planted links to one file are two files).
        // A file named on the command line is written through a link: by where it leads.
        std::error_code ec;
        const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
        const fs::path same =
            inside ? fs::weakly_canonical(folder, ec) / path.filename() : fs::weakly_canonical(path, ec);
        const std::string key = ec ? shown : same.string();
        if (names_.count(key)) throw InputError(shown + ": named twice in one output; give each its own name");
        auto file = std::unique_ptr<File>(new File());
        file->path_ = shown;
        file->key_ = key;
        // Inside an output folder a link in the file's place is replaced (renamed over), so the file
        // is written there whatever the link names.
        file->direct_ = !inside && writes_directly(path);
        if (!file->direct_) {
            struct stat own {};
            const bool link = !inside && ::lstat(path.c_str(), &own) == 0 && S_ISLNK(own.st_mode);
            const fs::path target = link ? fs::canonical(path, ec) : path;
            if (ec) throw InputError(shown + ": cannot write: " + ec.message());
            file->final_ = target.string();
            file->temporary_ = temporary_name(target, "tmp");
        }
        names_.insert(key);
        files_.push_back(std::move(file));
        return *files_.back();
    }

    /// Whether `folder` is an output_folder() or inside one; InputError when a folder between
    /// that output folder and `folder` is a symbolic link (not followed: refused).
    bool refuse_links_inside(const std::filesystem::path& folder) const {
        const std::filesystem::path f = folder.lexically_normal();
        for (const auto& root : roots_) {
            const std::filesystem::path rest = f.lexically_relative(root);
            if (rest.empty() || *rest.begin() == "..") continue;
            std::filesystem::path p = root;
            for (const auto& part : rest) {
                if (part == "." || part.empty()) continue;
                p /= part;
                struct stat st {};
                if (::lstat(p.c_str(), &st) == 0 && S_ISLNK(st.st_mode))
                    throw InputError(p.string() +
                                     ": is a symbolic link: inside an output folder pride writes only into folders "
                                     "it finds or makes there, never through a link");
            }
            return true;
        }
        return false;
    }

    /// ".NAME.pride-PID-N.KIND" beside `path`: hidden, unique within the process and its threads.
    static std::string temporary_name(const std::filesystem::path& path, const char* kind) {
        static std::atomic<unsigned long> next{0};
        const std::string name = "." + path.filename().string() + ".pride-" + std::to_string(::getpid()) + "-" +
                                 std::to_string(next++) + "." + kind;
        return (path.parent_path() / name).string();
    }
    void remove_scratch() noexcept {
        std::error_code ec;
        for (const auto& s : scratch_) std::filesystem::remove_all(s, ec);
        scratch_.clear();
    }

    std::vector<std::unique_ptr<File>> files_;
    std::set<std::string> names_;                 // every file's path, resolved: none named twice
    std::vector<std::filesystem::path> made_;     // folders this output made, outermost first
    std::vector<std::filesystem::path> roots_;    // output_folder()s: no link followed inside them
    std::vector<std::filesystem::path> scratch_;  // scratch folders, removed whatever happens
};

}  // namespace pride
