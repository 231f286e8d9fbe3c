// The header the spec-area fixture wrongly includes.
#pragma once
