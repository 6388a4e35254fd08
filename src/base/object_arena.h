// ObjectArena: owns the objects a scene is made of (shapes, textures, materials, lights,
// images) for the scene's lifetime, so the closed-set value types (Shape, Material, Light, ...)
// can hold plain pointers to them. Its MemoryBudget is what the objects may take
// (memory_budget.h): creation code charges large allocations to it before making them.
#pragma once

#include <memory>
#include <mutex>

#include <utility>
#include <vector>
#include "base/memory_budget.h"

namespace kiln {

class ObjectArena {
  public:
    ObjectArena() = default;
    // An arena that charges another arena's budget (a render job's, the scene's).
    explicit ObjectArena(MemoryBudget& shared) : budget_(&shared) {}
    ObjectArena(const ObjectArena&) = delete;
    ObjectArena& operator=(const ObjectArena&) = delete;
    // Objects are destroyed in reverse order of creation.
    ~ObjectArena() {
        while (!objects_.empty()) objects_.pop_back();
    }

    // Constructs a T that lives as long as the arena. Thread-safe.
    template <typename T, typename... Args>
    T* New(Args&&... args) {
        auto p = std::make_shared<T>(std::forward<Args>(args)...);
        T* raw = p.get();
        std::lock_guard<std::mutex> lock(mutex_);
        objects_.push_back(std::move(p));
        return raw;
    }

    MemoryBudget& Budget() { return *budget_; }
    const MemoryBudget& Budget() const { return *budget_; }

  private:
    MemoryBudget ownBudget_;
    MemoryBudget* budget_ = &ownBudget_;
    std::mutex mutex_;
    std::vector<std::shared_ptr<void>> objects_;
};

}  // namespace kiln
