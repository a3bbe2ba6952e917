// Typed names of what techniques hand each other, in the manner of Filament's blackboard: a GPU
// image or buffer of the frame graph (ImageName, BufferName), or a host-side value (HostName<T>:
// projections, counts, hooks) that lives in the technique publishing it. A consumer asks by name and
// gets the type the name declares, or nothing; it never sees the producer's class. The shared names
// are in core/names.h; a technique declares its further names in its own folder.
#pragma once
#include <map>
#include <stdexcept>
#include <string>
#include <typeindex>

namespace penumbra {

struct ImageName {
    const char* id;
};
struct BufferName {
    const char* id;
};
template <class T>
struct HostName {
    const char* id;
};

// Host-side entries by name. An entry points into its publisher, which drops its entries
// (dropOwner) before it goes; the renderer does that when it destroys a technique.
class Blackboard {
public:
    template <class T>
    void put(HostName<T> name, T* value, const void* owner) {
        entries_.insert_or_assign(name.id, Entry{value, std::type_index(typeid(T)), owner});
    }
    // Null when nobody published `name`; throws when it was published with another type.
    template <class T>
    T* get(HostName<T> name) const {
        const auto it = entries_.find(name.id);
        if (it == entries_.end()) return nullptr;
        if (it->second.type != std::type_index(typeid(T)))
            throw std::logic_error(std::string("blackboard: '") + name.id + "' holds another type");
        return static_cast<T*>(it->second.value);
    }
    template <class T>
    T& require(HostName<T> name) const {
        if (T* v = get(name)) return *v;
        throw std::logic_error(std::string("blackboard: nobody published '") + name.id + "'");
    }
    void dropOwner(const void* owner) {
        std::erase_if(entries_, [owner](const auto& e) { return e.second.owner == owner; });
    }
    void clear() { entries_.clear(); }

private:
    struct Entry {
        void* value;
        std::type_index type;
        const void* owner;
    };
    std::map<std::string, Entry> entries_;
};

}  // namespace penumbra
