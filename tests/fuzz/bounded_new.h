// tests/fuzz/bounded_new.h — for frame_vdb_fuzz.cpp only (include it in one file of one harness):
// the global operator new and delete of that harness, so that an allocation beyond
// kMaximumAllocationBytes throws std::bad_alloc as it does outside the sanitizers.
//
// Why: OpenVDB 10 allocates a compressed block's declared size before reading it
// (io::bloscFromStream, deep in the tree, beyond what io/vdb_file_header.h checks), up to 2^63
// bytes of which only what the file holds is ever written. Outside the sanitizers that ends in
// std::bad_alloc, which FrameSurface refuses as a corrupt grid; AddressSanitizer's own operator
// new never throws, it reports out-of-memory and aborts. These replacements forward to malloc
// (which AddressSanitizer still intercepts: overflows, use after free and leaks stay checked;
// only new/delete mismatches are no longer told apart) and throw above the bound. Memory really
// used stays bounded by -rss_limit_mb.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

namespace fluidsound::fuzz {

/// libFuzzer's -malloc_limit_mb=1024 (tests/fuzz/CMakeLists.txt, tools/fuzz.sh): above it new
/// throws before asking malloc, so libFuzzer's limit still catches every larger malloc of C code.
constexpr std::size_t kMaximumAllocationBytes = std::size_t{1024} << 20;

inline void* boundedAllocation(std::size_t size, std::size_t alignment) {
  if (size > kMaximumAllocationBytes) throw std::bad_alloc();
  void* memory =
      alignment <= alignof(std::max_align_t)
          ? std::malloc(size == 0 ? 1 : size)
          : std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
  if (memory == nullptr) throw std::bad_alloc();
  return memory;
}

}  // namespace fluidsound::fuzz

void* operator new(std::size_t size) { return fluidsound::fuzz::boundedAllocation(size, 0); }
void* operator new[](std::size_t size) { return fluidsound::fuzz::boundedAllocation(size, 0); }
void* operator new(std::size_t size, std::align_val_t a) {
  return fluidsound::fuzz::boundedAllocation(size, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
  return fluidsound::fuzz::boundedAllocation(size, static_cast<std::size_t>(a));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return fluidsound::fuzz::boundedAllocation(size, 0);
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
void* operator new(std::size_t size, std::align_val_t a, const std::nothrow_t&) noexcept {
  try {
    return fluidsound::fuzz::boundedAllocation(size, static_cast<std::size_t>(a));
  } catch (const std::bad_alloc&) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, std::align_val_t a, const std::nothrow_t& tag) noexcept {
  return operator new(size, a, tag);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
