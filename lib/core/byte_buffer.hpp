// Objects as bytes, for sending them between ranks: a writer that appends values and arrays of
// trivially copyable types (and strings), a reader that takes them back in the same order and
// refuses to read past the end, a broadcast of such bytes of any length, and work one rank does
// for the others, its result sent as bytes (the same to all, or each rank its own).
#pragma once

#include <mpi.h>

#include <cstdint>
#include <cstring>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "core/error.hpp"

namespace hpcontact {

class ByteWriter {
 public:
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const T& value) { append(&value, sizeof(T)); }
  template <class T>
  requires std::is_trivially_copyable_v<T>
  void put(const std::vector<T>& values) {
    put(static_cast<std::uint64_t>(values.size()));
    append(values.data(), values.size() * sizeof(T));
  }
  void put(const std::string& text) {
    put(static_cast<std::uint64_t>(text.size()));
    append(text.data(), text.size());
  }
  /// The bytes written, leaving the writer empty.
  std::vector<char> take() { return std::move(bytes_); }

 private:
  void append(const void* data, std::size_t size) {
    const auto* first = static_cast<const char*>(data);
    bytes_.insert(bytes_.end(), first, first + size);
  }
  std::vector<char> bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <class T>
  requires std::is_trivially_copyable_v<T> T get() {
    T value;
    copy_out(&value, sizeof(T));
    return value;
  }
  template <class T>
  requires std::is_trivially_copyable_v<T> std::vector<T> get_vector() {
    std::vector<T> values(get_count(sizeof(T)));
    copy_out(values.data(), values.size() * sizeof(T));
    return values;
  }
  std::string get_string() {
    std::string text(get_count(1), '\0');
    copy_out(text.data(), text.size());
    return text;
  }
  /// A count of objects that follow, each of at least `least_bytes` bytes, refused if what is left
  /// cannot hold them (a corrupt count must not allocate).
  std::size_t get_count(std::size_t least_bytes) {
    const auto count = get<std::uint64_t>();
    HPC_VERIFY(least_bytes == 0 || count <= (bytes_.size() - at_) / least_bytes, "bytes of an object cut short");
    return static_cast<std::size_t>(count);
  }
  bool at_end() const { return at_ == bytes_.size(); }

 private:
  void copy_out(void* data, std::size_t size) {
    HPC_VERIFY(size <= bytes_.size() - at_, "bytes of an object cut short");
    if (size > 0) std::memcpy(data, bytes_.data() + at_, size);
    at_ += size;
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

/// `bytes` of rank `root` on every rank of `ranks` (collective), whatever their length (sent in
/// pieces below MPI's int count limit).
std::vector<char> broadcast_bytes(std::vector<char> bytes, int root, MPI_Comm ranks);

/// Work that the first rank of `ranks` does alone for all of them: `make` runs there and returns
/// its result as bytes, which every rank returns; a failure of `make` is raised on every rank alike
/// (run_on_all_ranks_agreeing). Collective on `ranks`; on one rank it only runs `make`.
std::vector<char> bytes_made_by_first_rank(const std::function<std::vector<char>()>& make, MPI_Comm ranks);

/// Work that the first rank of `ranks` does alone for each of them: `make(r)` runs there for every
/// rank r of `ranks`, one after another, and rank r returns the bytes made for it (the first rank
/// holds one rank's bytes at a time). A failure of `make` is raised on every rank alike. Collective
/// on `ranks`; on one rank it only runs `make(0)`.
std::vector<char> bytes_made_by_first_rank_for_each(const std::function<std::vector<char>(int rank)>& make,
                                                    MPI_Comm ranks);

}  // namespace hpcontact
