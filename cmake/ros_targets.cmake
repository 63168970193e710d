# Nodelets, nodes and rostests (the ROS layer, ros/).
