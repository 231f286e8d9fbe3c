// The cache-area header the base-area fixture wrongly includes.
#pragma once
