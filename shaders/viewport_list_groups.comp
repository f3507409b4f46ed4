// shaders/viewport_list_groups.comp — sets the group counts of the indirect dispatches over the
// shade and march lists (viewport_common.glsl) from their entry counts, in one invocation after
// the passes that append. Counting a group as its first entry was appended cost the full-screen
// march pass an atomicAdd per pixel for each list, appending or not (llvmpipe loops over the SIMD
// lanes of every atomic, and runs both sides of every branch). Needs viewport_common.glsl.
layout(local_size_x = 1) in;

void main() {
    sl_groupsX = (sl_count + SHADE_GROUP - 1u) / SHADE_GROUP;
    ml_groupsX = (ml_count + SHADE_GROUP - 1u) / SHADE_GROUP;
}
