// The C boundary's plumbing: handle registry, exception -> result code translation, argument checks.
#pragma once
#include <cmath>
#include <mutex>
#include <new>
#include <string>
#include <unordered_set>

#include "core/error.h"
#include "octocap/octocap.h"

namespace octocap::internal::capi {

void set_last_error(const std::string& message);
void clear_last_error();

// Live handles of one type. Lookups never dereference the pointer, so a dangling handle is caught
// without touching freed memory.
template <class T>
class Registry {
 public:
  static Registry& instance() {
    static Registry r;
    return r;
  }
  void add(const T* p) {
    std::lock_guard<std::mutex> lock(mutex_);
    live_.insert(p);
  }
  bool remove(const T* p) {
    std::lock_guard<std::mutex> lock(mutex_);
    return live_.erase(p) > 0;
  }
  bool contains(const T* p) {
    std::lock_guard<std::mutex> lock(mutex_);
    return live_.count(p) > 0;
  }

 private:
  std::mutex mutex_;
  std::unordered_set<const T*> live_;
};

template <class T>
T* checked(T* handle, const char* what) {
  if (!handle) throw Error(Errc::invalid_handle, std::string(what) + " handle is NULL");
  if (!Registry<std::remove_const_t<T>>::instance().contains(handle))
    throw Error(Errc::invalid_handle, std::string(what) + " handle is not a live handle (destroyed or never created)");
  return handle;
}

template <class T>
void require(const T* pointer, const char* name) {
  if (!pointer) throw Error(Errc::invalid_argument, std::string(name) + " is NULL");
}

inline void require_finite(double v, const char* name) {
  if (!std::isfinite(v)) throw Error(Errc::invalid_argument, std::string(name) + " is NaN or infinite");
}

// Runs fn, mapping every exception to a result code and a last-error message. Nothing escapes.
template <class F>
octocap_result_t guard(F&& fn) noexcept {
  try {
    fn();
    return OCTOCAP_OK;
  } catch (const Error& e) {
    set_last_error(e.what());
    return static_cast<octocap_result_t>(e.code());
  } catch (const std::bad_alloc&) {
    set_last_error("out of memory");
    return OCTOCAP_ERROR_OUT_OF_MEMORY;
  } catch (const std::exception& e) {
    set_last_error(std::string("internal error: ") + e.what());
    return OCTOCAP_ERROR_INTERNAL;
  } catch (...) {
    set_last_error("internal error: unknown exception");
    return OCTOCAP_ERROR_INTERNAL;
  }
}

void copy_name(char* dst, size_t capacity, const std::string& src);
// A char array's text: NUL-terminated within `capacity` (Error(invalid_argument) naming `what` otherwise), maybe empty.
std::string c_text(const char* src, size_t capacity, const char* what);

// A call that worked but produced nothing returns a positive status, not OK and not an error.
inline octocap_result_t status_unless(octocap_result_t r, bool produced, octocap_result_t status) {
  return r == OCTOCAP_OK && !produced ? status : r;
}

}  // namespace octocap::internal::capi
