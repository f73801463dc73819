#pragma once
// Replacing a file with a new version (an image rewritten, a scene saved with a new camera):
// written beside it under a temporary name and renamed over it, so that a failure never leaves it
// half-written. What is replaced is the file a symbolic link leads to (the link stays a link, as
// `cp` and a shell's `>` write through one), and the new file keeps the old one's permissions
// (and owner and group where this user may set them): rewriting a 0600 image leaves it 0600.
#include <sys/types.h>

#include <string>

namespace whitted {

struct ReplaceTarget {
    std::string path;     // the file to replace: `path` itself, or where its links lead
    bool exists = false;  // (the rest is of the file there, when it exists)
    mode_t mode = 0;      // permission bits
    uid_t owner = 0;
    gid_t group = 0;
    nlink_t links = 0;    // its hard links: more than one, and a rename leaves the others the old file
};

// The file writing `path` replaces, links followed (a dangling link: the file it names).
ReplaceTarget replace_target(const std::string& path);

// Gives the new file open on `fd` the old file's permissions, owner and group (each as far as
// allowed; a file of another owner becomes this user's).
void keep_permissions(int fd, const ReplaceTarget& target);

}  // namespace whitted
