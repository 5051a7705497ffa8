// tests/support/steel_plate_model.h — a free steel plate's modal model for the solids' tests: a
// side × 0.01 × side m plate of 1 cm voxels, y up, centred on its body frame's origin (as a
// RigidWorld box of half extents (side/2, 0.005, side/2) is).
#pragma once

#include "acoustics/modal/modal_analysis.h"
#include "acoustics/modal/solid_material.h"
#include "acoustics/modal/voxel_solid.h"

namespace fluidsound::test {

/// Its lowest `modes` elastic modes (ModalSettings' other defaults).
inline acoustics::ModalModel steelPlateModel(double side, int modes) {
  acoustics::VoxelSolid plate = acoustics::voxelBox({side, 0.01, side}, 0.01);
  plate.origin = {-0.5 * side, -0.005, -0.5 * side};
  acoustics::ModalSettings settings;
  settings.maxModes = modes;
  return acoustics::analyseModes(plate, *acoustics::findSolidMaterial("steel"), settings);
}

}  // namespace fluidsound::test
