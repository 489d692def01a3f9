// A stream buffer over a file descriptor that keeps the errno of the write that failed, so that a
// full disk is reported as "No space left on device" rather than as a stream that went bad
// (std::filebuf does not say why a write failed). Seeks write what is buffered first.
#pragma once

#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace swarmnet {

class FileBuffer final : public std::streambuf {
 public:
  FileBuffer(int fd, std::size_t capacity);

  // Writes what is buffered; false when this or an earlier write failed (error() says why).
  bool drain();
  // The errno of the first write or seek that failed; 0 if none did.
  [[nodiscard]] int error() const { return error_; }

 protected:
  int_type overflow(int_type c) override;
  int sync() override;
  pos_type seekoff(off_type off, std::ios_base::seekdir dir,
                   std::ios_base::openmode which) override;
  pos_type seekpos(pos_type pos, std::ios_base::openmode which) override;

 private:
  int fd_;
  std::vector<char> buffer_;
  int error_ = 0;
};

// Why writing to `out` failed: the system's reason when it writes through a FileBuffer (an
// AtomicFile's stream), else that the stream failed.
std::string write_failure(std::ostream& out);

}  // namespace swarmnet
