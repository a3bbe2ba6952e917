// Large triangles whose lists are full go to the overflow pass (raster/overflow.comp): one workgroup
// of RASTER_OVERFLOW_GROUP threads per (triangle, part), a part at most RASTER_OVERFLOW_TILES tiles of
// its box, so that no thread's work grows with the layer's size.
#define RASTER_OVERFLOW_GROUP 64
#define RASTER_OVERFLOW_TILES 16
