#pragma once
// A std::vector whose resize() leaves new trivial elements uninitialised (default-initialised):
// for arrays that a parallel loop fills completely right after, so their pages are first
// touched by every thread instead of being zeroed by one.
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace tubemesh {

template <class T, class Base = std::allocator<T>>
struct DefaultInitAllocator : Base {
    using Base::Base;
    template <class U>
    struct rebind {
        using other = DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
    };
    template <class U>
    void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
        ::new (static_cast<void*>(p)) U;
    }
    template <class U, class... Args>
    void construct(U* p, Args&&... args) {
        std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
    }
};

template <class T>
using UninitVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace tubemesh
