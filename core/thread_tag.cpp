#include "core/thread_tag.hpp"

namespace mc {

namespace {
// Plain thread-local storage of the executable (the library is static): a signal handler reads
// it without a call that could allocate.
thread_local const char* t_tag = nullptr;
}  // namespace

const char* thread_tag() { return t_tag; }

ThreadTagScope::ThreadTagScope(const char* tag) : previous_(t_tag) { t_tag = tag; }

ThreadTagScope::~ThreadTagScope() { t_tag = previous_; }

}  // namespace mc
