#pragma once
// Keyframed rigid-body animation (thesis section 4.3): tracks of values at increasing times,
// sampled at any time by interpolating between the two keys around it, holding the first and
// last values outside the keyed span. Translation, scale and camera points interpolate linearly;
// rotations are unit quaternions interpolated by slerp along the shorter arc.

#include <stdexcept>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "rtu/model_header.h"

namespace rtu {

template <class Value>
struct Key {
  double time = 0.0;  // seconds
  Value value;
};

template <class Value>
class Track {
 public:
  // Throws std::invalid_argument unless `time` is later than the last key's.
  void add(double time, Value value) {
    if (!keys_.empty() && !(time > keys_.back().time))
      throw std::invalid_argument("key times must increase");
    keys_.push_back({time, value});
  }
  bool empty() const { return keys_.empty(); }
  const std::vector<Key<Value>>& keys() const { return keys_; }

  // `interpolate(a, b, fraction)` between the keys around `time`; `unset` for an empty track.
  template <class Interpolate>
  Value at(double time, Interpolate interpolate, const Value& unset) const {
    if (keys_.empty()) return unset;
    if (time <= keys_.front().time) return keys_.front().value;
    for (size_t i = 1; i < keys_.size(); ++i)
      if (time < keys_[i].time) {
        const Key<Value>& a = keys_[i - 1];
        const Key<Value>& b = keys_[i];
        return interpolate(a.value, b.value, (time - a.time) / (b.time - a.time));
      }
    return keys_.back().value;
  }

 private:
  std::vector<Key<Value>> keys_;
};

glm::dvec3 lerpVector(const glm::dvec3& a, const glm::dvec3& b, double fraction);
// Along the shorter arc (q and -q are one rotation); the result is unit length.
glm::dquat slerpShorter(const glm::dquat& a, const glm::dquat& b, double fraction);

// An instance's placement over time: model_header.h's ModelPlacement at any time. An empty track
// holds the identity (no translation, no rotation, scale 1).
struct PlacementTracks {
  Track<glm::dvec3> translation;
  Track<glm::dquat> rotation;
  Track<glm::dvec3> scale;

  ModelPlacement at(double time) const;
};

// The degrees of rotationFromEulerDegrees as a quaternion.
glm::dquat quaternionFromEulerDegrees(const glm::dvec3& degrees);

}  // namespace rtu
