#include "liquid/placement.h"

#include <glm/gtc/matrix_transform.hpp>

namespace liquid {

glm::mat4 Placement::world_from_liquid() const {
  return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
         glm::scale(glm::mat4(1.0f), glm::vec3(scale));
}

}  // namespace liquid
