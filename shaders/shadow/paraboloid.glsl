// The paraboloid mapping (Brabec et al. 2002) shared by the depth pass and the lookup. `v` is in the
// hemisphere's view space (forward = -z). A direction at angle theta from the axis lands at radius
// k tan(theta / 2): the 90-degree rim at k < 1, leaving a ring beyond it for filtering across the seam.
// Returns ndc.xy and the linear depth (d - near) / (far - near).
vec3 paraboloidProject(vec3 v, float near, float far, float discScale) {
    float d = length(v);
    float forward = -v.z;
    vec2 xy = discScale * v.xy / max(d + forward, 1e-6 * d);
    return vec3(xy, (d - near) / (far - near));
}

// cos of the widest angle from the axis that the disc holds (where k tan(theta / 2) = 1).
float paraboloidRimCos(float discScale) {
    float t = 1.0 / discScale;  // tan(theta_max / 2)
    return (1.0 - t * t) / (1.0 + t * t);
}
