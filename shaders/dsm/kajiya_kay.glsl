// Kajiya-Kay (1989) hair shading for a strand with unit tangent t, lit from l, seen from v (unit
// vectors away from the surface), per unit irradiance facing the light. Diffuse: a thin cylinder
// reflects in proportion to sin(t, l), scaled like a Lambertian surface (albedo / pi). Specular: the
// light mirrors into a cone around t (t.r = -t.l); its strength falls with the angle between v and
// that cone, cos = sin(t,l) sin(t,v) - (t.l)(t.v), raised to a power (energy-normalised), times
// sin(t, l) so that light along the strand gives none. The highlight is white (cuticle reflection).
const float HAIR_SPECULAR = 0.08;
const float HAIR_EXPONENT = 60.0;

vec3 kajiyaKay(vec3 albedo, vec3 t, vec3 l, vec3 v) {
    float tl = dot(t, l), tv = dot(t, v);
    float sinTL = sqrt(max(0.0, 1.0 - tl * tl)), sinTV = sqrt(max(0.0, 1.0 - tv * tv));
    float cone = max(0.0, sinTL * sinTV - tl * tv);
    float specular = HAIR_SPECULAR * (HAIR_EXPONENT + 2.0) / (2.0 * PI) * pow(cone, HAIR_EXPONENT);
    return (albedo / PI + vec3(specular)) * sinTL;
}
