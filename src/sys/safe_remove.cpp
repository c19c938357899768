// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "sys/safe_remove.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <unistd.h>

#include <vector>

namespace armstudy::sys {

bool stat_at(int dir_fd, const std::string& name, struct stat* st) {
  return ::fstatat(dir_fd, name.c_str(), st, AT_SYMLINK_NOFOLLOW) == 0;
}

int open_folder(const std::filesystem::path& path) {
  return ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
}

std::vector<std::string> list_folder(int dir_fd) {
  std::vector<std::string> names;
  const int fd = ::dup(dir_fd);
  if (fd < 0) return names;
  DIR* d = ::fdopendir(fd);
  if (!d) {
    ::close(fd);
    return names;
  }
  ::rewinddir(d);
  while (const dirent* e = ::readdir(d)) {
    const std::string n = e->d_name;
    if (n != "." && n != "..") names.push_back(n);
  }
  ::closedir(d);
  return names;
}

int open_folder_at(int dir_fd, const std::string& name) {
  return ::openat(dir_fd, name.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
}

size_t remove_tree_at(int dir_fd, const std::string& name) {
  struct stat st {};
  if (name.empty() || name == "." || name == ".." || !stat_at(dir_fd, name, &st)) return 0;
  if (!S_ISDIR(st.st_mode)) return ::unlinkat(dir_fd, name.c_str(), 0) == 0 ? 1 : 0;
  size_t removed = 0;
  // O_NOFOLLOW: a link swapped in since the lstat fails to open, and is left for the
  // unlinkat below (which removes a link, or fails on a folder that is not empty)
  const int fd = open_folder_at(dir_fd, name);
  if (fd >= 0) {
    struct stat opened {};
    if (::fstat(fd, &opened) == 0 && opened.st_dev == st.st_dev && opened.st_ino == st.st_ino)
      for (const std::string& n : list_folder(fd)) removed += remove_tree_at(fd, n);
    ::close(fd);
  }
  if (::unlinkat(dir_fd, name.c_str(), AT_REMOVEDIR) == 0) return removed + 1;
  // a link swapped in meanwhile is removed, never followed
  if (stat_at(dir_fd, name, &st) && S_ISLNK(st.st_mode) && ::unlinkat(dir_fd, name.c_str(), 0) == 0)
    ++removed;
  return removed;
}

}  // namespace armstudy::sys
