// ObjectArena: owns the objects a scene is made of (shapes, textures, materials, lights,
// images) for the scene's lifetime, so the closed-set value types (Shape, Material, Light, ...)
// can hold plain pointers to them. Its MemoryBudget is what the objects may take
// (memory_budget.h): creation code charges large allocations to it before making them.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <typeindex>
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

    // The T stored for `key` (a file's resolved name) and type by the first call that
    // finished making one: make() (returning T) runs when none is stored, so objects that
    // several scene directives load from one file are made once (scene creation is
    // sequential). Thread-safe: make() runs without the arena's lock, so racing calls may
    // each make one; all return the one stored first.
    template <typename T, typename Make>
    T* Shared(const std::string& key, Make&& make) {
        const std::pair<std::type_index, std::string> id(typeid(T), key);
        {
            std::lock_guard<std::mutex> lock(mutex_);
            if (auto it = shared_.find(id); it != shared_.end()) return static_cast<T*>(it->second);
        }
        T* created = New<T>(make());
        std::lock_guard<std::mutex> lock(mutex_);
        return static_cast<T*>(shared_.emplace(id, created).first->second);
    }

    MemoryBudget& Budget() { return *budget_; }
    const MemoryBudget& Budget() const { return *budget_; }

  private:
    MemoryBudget ownBudget_;
    MemoryBudget* budget_ = &ownBudget_;
    std::mutex mutex_;
    std::vector<std::shared_ptr<void>> objects_;
    std::map<std::pair<std::type_index, std::string>, void*> shared_;
};

}  // namespace kiln
