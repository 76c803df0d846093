// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A record's part by what names it: a power trace's channel by name or quantity, a sustained run's clock or
// temperature series by name. find_item gives null when there is none (for tests of absence); item_of throws,
// naming what was looked for, for tests that go on to read the part.
#include <stdexcept>
#include <string>
#include <vector>

namespace bs::test {

template <class Item, class Field, class Value>
const Item* find_item(const std::vector<Item>& items, Field Item::*field, const Value& value) {
  for (const auto& item : items)
    if (item.*field == value) return &item;
  return nullptr;
}

template <class Item, class Field, class Value>
const Item& item_of(const std::vector<Item>& items, Field Item::*field, const Value& value, const std::string& what) {
  if (const Item* item = find_item(items, field, value)) return *item;
  throw std::runtime_error("no " + what);
}

}  // namespace bs::test
