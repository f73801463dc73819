#include "base/file_replace.h"

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

namespace whitted {

ReplaceTarget replace_target(const std::string& path) {
    namespace fs = std::filesystem;
    ReplaceTarget t;
    t.path = path;
    std::error_code ec;
    if (fs::is_symlink(path, ec)) {
        const fs::path real = fs::weakly_canonical(fs::absolute(path, ec), ec);
        if (!ec) t.path = real.string();
    }
    struct stat st {};
    if (::stat(t.path.c_str(), &st) == 0) {
        t.exists = true;
        t.mode = st.st_mode & 07777;
        t.owner = st.st_uid;
        t.group = st.st_gid;
        t.links = st.st_nlink;
    }
    return t;
}

void keep_permissions(int fd, const ReplaceTarget& target) {
    if (!target.exists) return;
    // The group first (a member may set it), then the owner (root only); then the mode, which a
    // change of owner may have cleared of set-id bits.
    (void)!::fchown(fd, uid_t(-1), target.group);
    (void)!::fchown(fd, target.owner, uid_t(-1));
    (void)!::fchmod(fd, target.mode);
}

}  // namespace whitted
