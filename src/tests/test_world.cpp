#include <gtest/gtest.h>

#include "physics/world.h"

TEST(World, AddSphereGrowsEveryArray) {
    physics::World world;
    world.addSphere({0, 0, 1}, {1, 0, 0}, 0.1, 2.0);
    world.addSphere({0, 0, 2}, {0, 1, 0}, 0.2, 3.0);
    ASSERT_EQ(world.size(), 2u);
    EXPECT_EQ(world.velocity.size(), 2u);
    EXPECT_EQ(world.radius[1], 0.2);
    EXPECT_EQ(world.mass[1], 3.0);
    EXPECT_EQ(world.contactState.size(), 2u);
    world.removeSphere(0);
    ASSERT_EQ(world.size(), 1u);
    EXPECT_EQ(world.position[0].z, 2.0);
}
