// Fixture: a folder with no layer
#pragma once
