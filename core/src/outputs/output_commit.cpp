#include "outputs/output_commit.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "outputs/run_error.hpp"

namespace swarmnet {

OutputCommit::~OutputCommit() {
  std::error_code ignored;
  if (!kept_) {
    for (const Entry& entry : renamed_) std::filesystem::remove(entry.final_path, ignored);
  }
  for (const Entry& entry : added_) std::filesystem::remove(entry.temporary, ignored);
}

void OutputCommit::add(AtomicFile& file) {
  file.hand_over();
  added_.push_back({file.temporary(), file.path()});
}

void OutputCommit::add(const std::filesystem::path& temporary,
                       const std::filesystem::path& final_path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(temporary, ec)) {
    throw RunError("cannot commit " + final_path.string() + ": " + temporary.string() +
                   " is missing");
  }
  added_.push_back({temporary, final_path});
}

void OutputCommit::rename_added() {
  while (!added_.empty()) {
    const Entry entry = added_.front();
    if (std::rename(entry.temporary.c_str(), entry.final_path.c_str()) != 0) {
      throw RunError("cannot rename " + entry.temporary.string() +
                     " into place: " + std::strerror(errno));
    }
    added_.erase(added_.begin());
    renamed_.push_back(entry);
  }
}

}  // namespace swarmnet
