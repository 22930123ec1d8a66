/* Ends an expansion of main/dlist_ops.h: undefines the DL_OP* macros its
 * includer defined (no include guard: included after every expansion). */
#undef DL_OP0
#undef DL_OP1
#undef DL_OP2
#undef DL_OP3
#undef DL_OP4
#undef DL_OP5
#undef DL_OP6
#undef DL_OPV0
#undef DL_OPV1
#undef DL_OPV2
#undef DL_CUSTOM0
#undef DL_CUSTOM1
#undef DL_CUSTOMV2
