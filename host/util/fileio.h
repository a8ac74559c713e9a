// fileio.h -- the one way lumibench reads input files and writes output files.
//
// Reading: readFile() refuses anything but a regular file (directories,
// FIFOs, devices such as /dev/zero, sockets: opened without blocking and
// checked) and anything larger than a stated limit before holding it in
// memory, with messages naming the file.
//
// Writing: every output (EXR, PNG, JSON, Markdown, LDT/IES, cache entries) is
// written to a temporary file in the target directory, flushed to disk
// (fsync) and renamed over the target only when every byte was written and
// the file closed without error. On failure the temporary file is removed and
// the target is left as it was: a full disk never leaves an empty or a
// truncated output behind. writeFilesAtomic() does this for a group (an image
// and its side files): all temporaries are written first, so a failure of any
// leaves none of them.
//
// A symbolic link at the output's path is never followed: the rename replaces
// the link itself, so a link planted in an output folder (report.html ->
// ~/.bashrc) cannot make lumibench write elsewhere. An existing device, FIFO
// or socket (--out /dev/null) is refused with an lb::InputError: a FIFO would
// block until a reader comes, and a rename would replace the device node
// itself. So is an empty path. Directories inside an output folder are made
// by createDirsBelow(), which refuses a link in their place.
//
// Temporary files are named TARGET.tmp.PID.SEQ. One left behind by a killed
// process (kill -9 cannot be caught) is removed by removeStaleTemporaries(),
// which deletes only those whose process no longer runs on this host.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lb::util {

// The whole file at `path`, at most `maxBytes` long. `what` names the kind
// of file in messages ("experiment file", "results file"). Throws
// lb::InputError: "PATH: expected WHAT, got a directory" (and likewise for a
// missing or unreadable file, or one over the limit).
std::string readFile(const std::string& path, const std::string& what, size_t maxBytes);

// Writes `bytes` to `path` atomically (see above); throws lb::Error naming the
// path and the system's reason.
void writeFileAtomic(const std::string& path, const std::string& bytes);

// Writes every (path, bytes) pair atomically as a group: all temporaries are
// written and flushed first; if any fails, all are removed and nothing is
// renamed. Throws lb::Error naming the path that failed.
void writeFilesAtomic(const std::vector<std::pair<std::string, std::string>>& files);

// Removes TARGET.tmp.PID[.SEQ] files in `dir` and every directory below it
// (links not followed) whose PID is not a running process; returns how many
// were removed. Errors are ignored (best effort).
size_t removeStaleTemporaries(const std::string& dir);

// Makes the directory root/rel and every one between them (root itself may be
// or lie below a link: the user named it). A symbolic link or anything but a
// directory at root/rel or between is refused with an lb::InputError naming
// it: a link there would carry the outputs out of the folder.
void createDirsBelow(const std::string& root, const std::string& rel);

// Refuses (lb::InputError naming it) a symbolic link at root/rel or anywhere
// below it: for outputs written by other programs (the plot scripts), which
// would follow it. `dirsOnly`: only links to directories (where files are
// written by writeFileAtomic, which replaces a link to a file).
void refuseLinksBelow(const std::string& root, const std::string& rel, bool dirsOnly = false);

// Copies every regular file below directory `from` to the same place below
// `to` (directories created by createDirsBelow, existing files replaced), each file written
// atomically as above: a full disk or a kill leaves each target whole or as
// it was, never a 0-byte or truncated copy. Links and special files are
// skipped. Throws lb::Error naming the file that failed.
void copyTreeAtomic(const std::string& from, const std::string& to);

// Tests: replaces how a temporary file is opened. The opener gets the
// temporary path and returns a writable file descriptor (or -1 with errno
// set). A test can create the file and then dup2 /dev/full onto the
// descriptor, so that every write fails with ENOSPC as on a full disk.
// An empty function restores the default (open(2) with O_CREAT | O_EXCL).
using TempOpener = std::function<int(const std::string& tmpPath)>;
void setTempOpenerForTesting(TempOpener opener);

}  // namespace lb::util
