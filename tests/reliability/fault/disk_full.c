/* A disk that fills up, for the reliability tests (LD_PRELOAD=libchoc_disk_full.so).
 *
 *   CHOC_DISK_FULL_DIR=dir       the output directory: only writes to files under it count
 *   CHOC_DISK_FULL_TRIGGER=text  the disk fills during a write to a file whose path holds text
 *                                (".exo.part", ".history.csv.part")
 *   CHOC_DISK_FULL_AFTER=bytes   ... once that many bytes went to such files
 *
 * The write that crosses the limit stores only what fits (a short write, as a full disk does);
 * from then on every write to a file under the directory fails with ENOSPC, whatever the file
 * (the checkpoint's too). write, pwrite, pwrite64 and writev are interposed: glibc's stdio and
 * netCDF reach the kernel through them. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/types.h>
#include <sys/uio.h>
#include <unistd.h>

static long long g_budget = -1;  /* bytes the trigger files may still take; < 0: not set up */
static int g_full = 0;

static void setup(void) {
  if (g_budget != -1) return;
  const char* after = getenv("CHOC_DISK_FULL_AFTER");
  g_budget = after ? atoll(after) : (1LL << 62);
}

/* 0: not under the directory; 1: under it; 2: under it and a trigger file. */
static int classify(int fd) {
  const char* dir = getenv("CHOC_DISK_FULL_DIR");
  const char* trigger = getenv("CHOC_DISK_FULL_TRIGGER");
  if (!dir) return 0;
  char link[64], path[4096];
  snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
  const ssize_t n = readlink(link, path, sizeof path - 1);
  if (n <= 0) return 0;
  path[n] = '\0';
  if (strncmp(path, dir, strlen(dir)) != 0) return 0;
  return trigger && strstr(path, trigger) ? 2 : 1;
}

/* How many of `count` bytes the disk takes now (-1: none, errno set). */
static ssize_t allowed(int fd, size_t count) {
  setup();
  const int kind = classify(fd);
  if (kind == 0) return (ssize_t)count;
  if (g_full) {
    errno = ENOSPC;
    return -1;
  }
  if (kind == 1) return (ssize_t)count;
  if ((long long)count <= g_budget) {
    g_budget -= (long long)count;
    return (ssize_t)count;
  }
  g_full = 1;
  const ssize_t part = (ssize_t)g_budget;
  g_budget = 0;
  if (part == 0) {
    errno = ENOSPC;
    return -1;
  }
  return part;
}

ssize_t write(int fd, const void* buf, size_t count) {
  static ssize_t (*real)(int, const void*, size_t);
  if (!real) real = (ssize_t(*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
  const ssize_t n = allowed(fd, count);
  return n < 0 ? -1 : real(fd, buf, (size_t)n);
}

ssize_t pwrite(int fd, const void* buf, size_t count, off_t offset) {
  static ssize_t (*real)(int, const void*, size_t, off_t);
  if (!real) real = (ssize_t(*)(int, const void*, size_t, off_t))dlsym(RTLD_NEXT, "pwrite");
  const ssize_t n = allowed(fd, count);
  return n < 0 ? -1 : real(fd, buf, (size_t)n, offset);
}

ssize_t pwrite64(int fd, const void* buf, size_t count, off_t offset) {
  static ssize_t (*real)(int, const void*, size_t, off_t);
  if (!real) real = (ssize_t(*)(int, const void*, size_t, off_t))dlsym(RTLD_NEXT, "pwrite64");
  const ssize_t n = allowed(fd, count);
  return n < 0 ? -1 : real(fd, buf, (size_t)n, offset);
}

ssize_t writev(int fd, const struct iovec* iov, int iovcnt) {
  static ssize_t (*real)(int, const struct iovec*, int);
  if (!real) real = (ssize_t(*)(int, const struct iovec*, int))dlsym(RTLD_NEXT, "writev");
  size_t total = 0;
  for (int i = 0; i < iovcnt; ++i) total += iov[i].iov_len;
  const ssize_t n = allowed(fd, total);
  if (n < 0) return -1;
  if ((size_t)n == total) return real(fd, iov, iovcnt);
  /* a short write: the first n bytes only */
  ssize_t done = 0;
  for (int i = 0; i < iovcnt && done < n; ++i) {
    size_t take = iov[i].iov_len;
    if ((ssize_t)take > n - done) take = (size_t)(n - done);
    static ssize_t (*realw)(int, const void*, size_t);
    if (!realw) realw = (ssize_t(*)(int, const void*, size_t))dlsym(RTLD_NEXT, "write");
    const ssize_t w = realw(fd, iov[i].iov_base, take);
    if (w < 0) return done > 0 ? done : -1;
    done += w;
  }
  return done;
}
