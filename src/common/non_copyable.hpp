#pragma once
// A base for owners of one resource (a GL context, a log hook) that must never be copied.

namespace bookspin {

class NonCopyable {
 public:
  NonCopyable(const NonCopyable&) = delete;
  NonCopyable& operator=(const NonCopyable&) = delete;

 protected:
  NonCopyable() = default;
  ~NonCopyable() = default;
};

}  // namespace bookspin
