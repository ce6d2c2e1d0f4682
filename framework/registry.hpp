#pragma once
// A registry: names to entries, with a few words each, in the order they were added (the catalog
// of continuous functions). Types are chosen at run time in engine/ and nowhere else.
#include <string>
#include <string_view>
#include <vector>

namespace pride {

template <class Entry>
class Registry {
  public:
    struct Item {
        std::string name;
        std::string summary;
        Entry entry;
    };

    Registry& add(std::string name, std::string summary, Entry entry) {
        items_.push_back(Item{std::move(name), std::move(summary), std::move(entry)});
        return *this;
    }

    const Item* find(std::string_view name) const {
        for (const auto& item : items_)
            if (item.name == name) return &item;
        return nullptr;
    }

    const std::vector<Item>& items() const { return items_; }

  private:
    std::vector<Item> items_;
};

}  // namespace pride
