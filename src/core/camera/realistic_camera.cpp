#include "core/camera/realistic_camera.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace kiln {

RealisticCamera::RealisticCamera(const CameraTransform& cameraTransform, Float shutterOpen,
                                 Float shutterClose, Point2i fullResolution, Float filmDiagonal,
                                 LensSystem lensSystem, int pupilSamples)
    : CameraBase(cameraTransform, shutterOpen, shutterClose),
      fullResolution(fullResolution),
      filmDiagonal(filmDiagonal),
      lens(std::move(lensSystem)) {
    Float aspect = Float(fullResolution.y) / Float(fullResolution.x);
    Float x = std::sqrt(Sqr(filmDiagonal) / (1 + Sqr(aspect))), y = aspect * x;
    physicalExtent = Bounds2f{Point2f(-x / 2, -y / 2), Point2f(x / 2, y / 2)};

    const int nRings = 64;
    exitPupilBounds.resize(nRings);
    tbb::parallel_for(0, nRings, [&](int i) {
        Float r0 = Float(i) / nRings * filmDiagonal / 2;
        Float r1 = Float(i + 1) / nRings * filmDiagonal / 2;
        exitPupilBounds[i] = lens.BoundExitPupil(r0, r1, pupilSamples);
    });
    FindMinimumDifferentials(*this, fullResolution);
}

const PupilBounds& RealisticCamera::ExitPupilBounds(Float r) const {
    int i = int(r / (filmDiagonal / 2) * exitPupilBounds.size());
    return exitPupilBounds[std::clamp<int>(i, 0, int(exitPupilBounds.size()) - 1)];
}

Point3f RealisticCamera::FilmPoint(Point2f pRaster) const {
    Point2f s(pRaster.x / fullResolution.x, pRaster.y / fullResolution.y);
    Float px = Lerp(s.x, physicalExtent.pMin.x, physicalExtent.pMax.x);
    Float py = Lerp(s.y, physicalExtent.pMin.y, physicalExtent.pMax.y);
    return Point3f(-px, py, 0);
}

std::optional<CameraRay> RealisticCamera::GenerateRay(const CameraSample& sample,
                                                      SampledWavelengths& lambda) const {
    (void)lambda;
    Point3f pFilm = FilmPoint(sample.pFilm);
    // A point in the exit pupil bounds of this film radius, rotated to the film point's azimuth
    Float filmRadius = std::sqrt(Sqr(pFilm.x) + Sqr(pFilm.y));
    const PupilBounds& pupil = ExitPupilBounds(filmRadius);
    if (pupil.IsDegenerate()) return std::nullopt;
    Point2f pLens = pupil.Lerp(sample.pLens);
    Float pdf = 1 / pupil.Area();
    Float sinPhi = filmRadius != 0 ? pFilm.y / filmRadius : 0,
          cosPhi = filmRadius != 0 ? pFilm.x / filmRadius : 1;
    Point3f pPupil(cosPhi * pLens.x - sinPhi * pLens.y, sinPhi * pLens.x + cosPhi * pLens.y,
                   lens.RearZ());

    Ray rFilm(pFilm, pPupil - pFilm), ray;
    Float weight = lens.TraceFromFilm(rFilm, &ray);
    if (!(weight > 0)) return std::nullopt;
    ray.time = SampleTime(sample.time);
    ray = cameraTransform.RenderFromCamera(ray);
    ray.d = Normalize(ray.d);
    Float cosAxis = Normalize(rFilm.d).z;
    weight *= Sqr(Sqr(cosAxis)) / (pdf * Sqr(lens.RearZ()));
    return CameraRay{ray, SampledSpectrum(weight)};
}

}  // namespace kiln
