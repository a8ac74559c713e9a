// run_lock.h -- one experiment at a time in one output folder.
//
// Shards of one experiment may run into one folder at once (each appends its
// own cells); two different experiments may not: both would keep their cells
// in one results.json, and the report would pool two experiments. A run holds
// a shared flock on DIR/results.json.run for as long as it writes; the first
// holder writes its experiment's identity into the file. A later run of the
// same identity joins; one of another is refused with an lb::InputError
// naming the experiment that is running. The check and the join happen under
// the results file's own lock (results.json.lock), so two runs starting
// together cannot both see the folder free. After the last holder exits (or
// is killed: the kernel drops its locks), the folder is free again.
#pragma once

#include <string>

namespace lb::experiments {

class RunLock {
public:
    // `identity`: equal for the shards of one experiment, different for any
    // other (a digest of the experiment); `name` and `file` only for messages.
    RunLock(const std::string& resultsPath, const std::string& identity, const std::string& name,
            const std::string& file);
    ~RunLock();
    RunLock(const RunLock&) = delete;
    RunLock& operator=(const RunLock&) = delete;

private:
    int fd_ = -1;
};

}  // namespace lb::experiments
