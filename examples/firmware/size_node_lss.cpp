// node_lss: size_node's node as an LSS slave too (capacity::lss, CiA 305: node/lss_slave.hpp):
// the difference to `node` is what LSS costs; `node` itself links none of it.
#define FIELDCODEC_SIZE_NODE_LSS
#include "size_node.cpp"
