#include "motion/component_set.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "core/text.h"

namespace caskdem::motion {

ComponentSet read_component_set(const std::filesystem::path& h1, const std::filesystem::path& h2,
                                const std::optional<std::filesystem::path>& vertical, const ReadOptions& options,
                                TailRule tails) {
  ComponentSet set;
  set.h1 = read_record(h1, options);
  set.h2 = read_record(h2, options);
  if (vertical) set.vertical = read_record(*vertical, options);
  std::vector<Record*> components = {&set.h1, &set.h2};
  if (set.vertical) components.push_back(&*set.vertical);

  for (const Record* c : components) {
    const double dt = set.h1.time_step;
    if (std::abs(c->time_step - dt) > 1e-6 * dt) {
      throw InputError(c->source + ": time step " + number_text(c->time_step) + " s, but " + set.h1.source + " has " +
                       number_text(dt) + " s; expected the components of one station, sampled alike");
    }
  }
  std::size_t shortest = components.front()->acceleration.size(), longest = shortest;
  for (const Record* c : components) {
    shortest = std::min(shortest, c->acceleration.size());
    longest = std::max(longest, c->acceleration.size());
  }
  if (shortest == longest) return set;

  const std::size_t length = tails == TailRule::trim ? shortest : longest;
  std::ostringstream note;
  note << "lengths";
  for (std::size_t k = 0; k < components.size(); ++k) note << (k ? ", " : " ") << components[k]->acceleration.size();
  note << " samples: " << (tails == TailRule::trim ? "trimmed to " : "padded with zeros to ") << length << " ("
       << number_text(set.h1.time_step * static_cast<double>(length - 1)) << " s)";
  set.time_base = note.str();
  for (Record* c : components) {
    c->time_step = set.h1.time_step;  // one time base: the first horizontal's step
    c->acceleration.resize(length, 0.0);
  }
  return set;
}

}  // namespace caskdem::motion
