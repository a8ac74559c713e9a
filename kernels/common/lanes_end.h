/* lanes_end.h -- see lanes1.h. */
#undef LB_V
#undef LB_I
#undef LB_M
#undef LB_VFN
#undef LB_TO_I
#undef LB_TO_V
#undef LB_U
#undef LB_TO_U
#undef LB_U_TO_V
#undef LB_GATHER
#undef LB_VINTENSITY3
#undef LB_NLANES
#undef LB_ANY
#undef LB_LANE_INDEX
#undef LB_STORE
