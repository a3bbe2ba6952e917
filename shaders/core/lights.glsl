// Irradiance arriving at p from one punctual light, on a surface facing the light (no cosine yet).
// `l` receives the unit direction from p towards the light. Falloff and spot cone follow
// KHR_lights_punctual: inverse square, range window (1 - (d/r)^4)^2, smooth cone t^2.
const float PI = 3.14159265358979;

vec3 incidentIrradiance(GpuLight light, vec3 p, out vec3 l) {
    uint type = light.type;
    if (type == LIGHT_DIRECTIONAL) {
        l = -light.direction;
        return light.radiance;
    }
    vec3 d = light.position - p;
    float dist2 = max(dot(d, d), 1e-8);
    float dist = sqrt(dist2);
    l = d / dist;
    float atten = 1.0 / dist2;
    float range = light.range;
    if (range > 0.0) {
        float x = dist / range;
        atten *= clamp(1.0 - x * x * x * x, 0.0, 1.0) * clamp(1.0 - x * x * x * x, 0.0, 1.0);
    }
    if (type == LIGHT_SPOT) {
        float cd = dot(-l, light.direction);
        float t = clamp((cd - light.cosOuter) / max(light.cosInner - light.cosOuter, 1e-4), 0.0, 1.0);
        atten *= t * t;
    }
    return light.radiance * atten;
}
