// Fixture
#pragma once
